// Scenario: one line of the Appendix-A scenario table (scenarios.tsv): a room, a start and the published figures
// of its run; and the table's reader.
#pragma once
#include <string>
#include <vector>

namespace nxtmap::report {

// One line of scenarios.tsv.
struct Scenario {
  std::string id;
  std::string map;      // as written in the table
  std::string mapPath;  // resolved against the table's directory
  int line = 0;         // line number in the table (1 = first line)
  int startCol = 0, startRow = 0;
  double seedXM = 0, seedZM = 0;
  int occupiedCells = 0;
  int seedUnknowns = 0;
  double seedTimeUnits = 0;
  int seedSensorCount = 0;
  double seedDetectedPct = 0;
  bool isOccupancyRun() const { return id.rfind("occ", 0) == 0; }
  bool isStartRun() const { return id.rfind("start", 0) == 0; }
};

struct ScenarioLoad {
  std::vector<Scenario> scenarios;
  std::string error;  // empty on success; names the file and line otherwise
};

// Reads a tab-separated scenario table ('#' lines are comments, blank lines skipped).
ScenarioLoad loadScenarios(const std::string& tsvPath);

}  // namespace nxtmap::report
