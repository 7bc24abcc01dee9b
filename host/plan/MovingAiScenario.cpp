#include "host/plan/MovingAiScenario.hpp"

#include <charconv>
#include <cmath>
#include <iterator>
#include <sstream>

#include "host/sim/InputFile.hpp"

namespace nxtmap::plan {
namespace {

// The largest scenario file read: Moving AI's biggest benchmark sets hold a few thousand problems of ~60 bytes.
constexpr size_t kMaxScenarioBytes = 32u << 20;

bool toInt(const std::string& s, int& out) {
  const auto res = std::from_chars(s.data(), s.data() + s.size(), out);
  return res.ec == std::errc() && res.ptr == s.data() + s.size();
}

bool toDouble(const std::string& s, double& out) {
  const auto res = std::from_chars(s.data(), s.data() + s.size(), out);
  return res.ec == std::errc() && res.ptr == s.data() + s.size() && std::isfinite(out);
}

}  // namespace

ScenarioLoad loadScenario(const std::string& path) {
  std::string error;
  const std::optional<std::string> bytes = sim::readInputFile(path, kMaxScenarioBytes, "scenario file", error);
  if (!bytes) return ScenarioLoad{std::nullopt, error};
  std::istringstream in(*bytes);
  std::vector<ScenarioProblem> problems;
  std::string line;
  int lineNo = 0;
  auto fail = [&](const std::string& what) {
    return ScenarioLoad{std::nullopt, path + ":" + std::to_string(lineNo) + ": " + what};
  };
  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    if (lineNo == 1) {
      if (w.size() != 2 || w[0] != "version" || (w[1] != "1" && w[1] != "1.0")) {
        return fail("not a Moving AI scenario file (expected 'version 1' first)");
      }
      continue;
    }
    if (w.empty()) continue;
    if (w.size() != 9)
      return fail("expected 9 fields (bucket map width height sx sy gx gy optimal), found " + std::to_string(w.size()));
    ScenarioProblem p;
    p.map = w[1];
    if (!toInt(w[0], p.bucket) || !toInt(w[2], p.mapWidth) || !toInt(w[3], p.mapHeight) || !toInt(w[4], p.start.col) ||
        !toInt(w[5], p.start.row) || !toInt(w[6], p.goal.col) || !toInt(w[7], p.goal.row) ||
        !toDouble(w[8], p.optimal) || p.optimal < 0.0) {
      return fail("bad number in '" + line + "'");
    }
    problems.push_back(p);
  }
  if (lineNo == 0) return fail("empty file (expected 'version 1')");
  return ScenarioLoad{std::move(problems), {}};
}

}  // namespace nxtmap::plan
