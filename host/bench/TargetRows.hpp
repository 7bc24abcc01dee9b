// TargetRows: a bench section's table of measures against their targets (PASS / MISS, or information), printed
// with its columns aligned and a count of the targets met.
#pragma once

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace nxtmap::bench {

inline const char* verdict(bool ok) { return ok ? "PASS" : "MISS"; }

// `result`: "PASS", "MISS" or "" (information, no target).
class TargetRows {
 public:
  void add(const std::string& measure, const std::string& what, const std::string& measured, const std::string& target,
           const std::string& result) {
    rows_.push_back({measure, what, measured, target, result});
    if (result == "PASS") ++pass_;
    if (result == "PASS" || result == "MISS") ++targets_;
  }
  void print() const {
    const std::vector<std::string> head = {"measure", "map / algorithm", "measured", "target", "result"};
    std::vector<size_t> w(head.size());
    for (size_t i = 0; i < head.size(); ++i) w[i] = head[i].size();
    for (const auto& r : rows_)
      for (size_t i = 0; i < r.size(); ++i) w[i] = std::max(w[i], r[i].size());
    auto line = [&](const std::vector<std::string>& r) {
      std::string s;
      for (size_t i = 0; i < r.size(); ++i) s += r[i] + std::string(w[i] - r[i].size() + 2, ' ');
      while (!s.empty() && s.back() == ' ') s.pop_back();
      std::cout << s << '\n';
    };
    line(head);
    size_t total = 0;
    for (size_t x : w) total += x + 2;
    std::cout << std::string(total - 2, '-') << '\n';
    for (const auto& r : rows_) line(r);
    std::cout << std::string(total - 2, '-') << '\n'
              << "path search targets met: " << pass_ << " of " << targets_ << '\n';
  }

 private:
  std::vector<std::vector<std::string>> rows_;
  int pass_ = 0, targets_ = 0;
};

}  // namespace nxtmap::bench
