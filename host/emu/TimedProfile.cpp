#include "host/emu/TimedProfile.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

namespace nxtmap::emu {
namespace {

std::string demangled(const std::string& name) {
  int status = 0;
  const std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status),
                                                 std::free);
  return status == 0 && d ? std::string(d.get()) : name;
}

}  // namespace

void TimedProfile::endCall(uint64_t total) {
  if (total <= worstTotal_) return;
  worstTotal_ = total;
  worst_.swap(current_);
}

std::vector<FunctionCost> TimedProfile::byFunction(const ElfImage& image) const {
  std::map<std::string, uint64_t> sums;
  for (const auto& [address, n] : worst_) {
    const FunctionSymbol* f = image.functionAt(address);
    if (f != nullptr) {
      sums[f->name] += n;
    } else {
      char b[16];
      std::snprintf(b, sizeof b, "?%08x", static_cast<unsigned>(address));
      sums[b] += n;
    }
  }
  std::vector<FunctionCost> out;
  for (const auto& [name, n] : sums) out.push_back(FunctionCost{demangled(name), n});
  std::sort(out.begin(), out.end(), [](const FunctionCost& a, const FunctionCost& b) {
    return a.instructions != b.instructions ? a.instructions > b.instructions : a.name < b.name;
  });
  return out;
}

std::string profileLines(const std::vector<FunctionCost>& costs, uint64_t total, size_t max) {
  std::string out;
  char line[64];
  for (size_t i = 0; i < costs.size() && i < max; ++i) {
    const double pct = total > 0 ? 100.0 * static_cast<double>(costs[i].instructions) / static_cast<double>(total) : 0;
    std::snprintf(line, sizeof line, "  %9llu  %5.1f %%  ", static_cast<unsigned long long>(costs[i].instructions),
                  pct);
    std::string name = costs[i].name;
    if (name.size() > 110) name = name.substr(0, 107) + "...";
    out += line + name + "\n";
  }
  return out;
}

}  // namespace nxtmap::emu
