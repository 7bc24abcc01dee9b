// MovingAiScenario: Moving AI ".scen" problem files (version 1): a "version 1" line, then one problem per
// line, tab-separated: bucket, map, map width, map height, start x, start y, goal x, goal y, optimal length.
// x is the column, y the row from the top. The optimum uses sqrt(2) diagonals and no corner cutting.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "host/plan/Traversability.hpp"

namespace nxtmap::plan {

struct ScenarioProblem {
  int bucket = 0;
  std::string map;  // the map file named by the line
  int mapWidth = 0, mapHeight = 0;
  MapCell start, goal;
  double optimal = 0.0;  // published optimal length, cells
};

struct ScenarioLoad {
  std::optional<std::vector<ScenarioProblem>> problems;
  std::string error;  // file:line: problem, when problems is empty
};

ScenarioLoad loadScenario(const std::string& path);

}  // namespace nxtmap::plan
