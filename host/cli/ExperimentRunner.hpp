// ExperimentRunner: loads a scenario table with its worlds and runs it for one strategy.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "host/mapping/MappingRun.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/Site.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::cli {

struct Suite {
  std::string tsvPath;
  int cellCm = 10;  // the layouts' cells: the robot's (10 published, 20 brick)
  std::vector<report::Scenario> scenarios;
  std::map<std::string, sim::World> worlds;  // by Scenario::mapPath
  std::map<std::string, sim::Site> sites;    // the same worlds traced into scenes
  const sim::World& world(const report::Scenario& s) const { return worlds.at(s.mapPath); }
  const sim::Site& site(const report::Scenario& s) const { return sites.at(s.mapPath); }
};

// DIR/scenarios.tsv (or the .tsv file itself) and every world it names, its layouts scaled to cells of cellCm
// (Moving AI maps have no resolution of their own: 10 cm as published, 20 cm for the brick); each start is
// checked. Throws CliError naming the file (and line) on any problem.
Suite loadSuite(const std::string& dirOrTsv, int cellCm = 10);

// How a suite is run: one strategy, one noise preset, seeds 1..seeds, one robot, set down square or not, on
// one room grid (the brick's unless chosen otherwise).
struct SuiteSettings {
  mapping::Strategy strategy = mapping::Strategy::Propagation;
  std::string noise = "ideal";
  int seeds = 1;
  sim::RobotDescription robot = *sim::robotByName("published");
  double startJitterDeg = 0.0;
  bool squareAtStart = false;  // the pilot turns square to the walls before mapping
  int calibrateTurns = 0;      // > 0: and measures its turns' error first (RunConfig::calibrateTurns)
  bool calibrateUnknownTurns = true;  // RunConfig::calibrateUnknownTurns
  mapping::GridCapacity grid = mapping::GridCapacity::brick();
  // Each run's robot first maps the suite's next layout with nothing stored (its first outing, the same seed:
  // the same wheels) and starts with the wheels it learnt there, as a brick keeps them from run to run.
  bool afterFirstOuting = false;
};

// A run that met the grid's edge (MappingRun::metGridEdge): its room was larger than the grid.
struct GridFullRun {
  std::string id;  // the scenario's
  int seed = 1;
  int roomCols = 0, roomRows = 0;  // the room on the robot's grid, cells
};

// The published set-up for a scenario: 1 m range, initial heading N (a point robot of the raster's cells).
mapping::RunConfig scenarioConfig(const report::Scenario& s, mapping::Strategy strategy, const sim::NoiseProfile& noise,
                                  uint64_t seed);
// The same for a robot and a start jitter.
mapping::RunConfig scenarioConfig(const report::Scenario& s, const SuiteSettings& settings, uint64_t seed);

// The wheels a robot (`seed`: its wheels' systematic errors) learns mapping `scenario` of the suite with
// nothing stored (Pilot::wheels at the run's end).
WheelCalibration firstOutingWheels(const Suite& suite, size_t scenario, const SuiteSettings& settings, uint64_t seed);

// Runs `run` to its end and gives its figures, the localisation counted after every action
// (mapping::PoseErrorShare).
report::RunResult runAndScore(mapping::MappingRun& run);
// The same, and the run (id, seed, room) added to `gridFull` when it met the grid's edge (nullptr: not recorded).
report::RunResult runAndScore(mapping::MappingRun& run, const std::string& id, std::vector<GridFullRun>* gridFull);
// One full run.
report::RunResult runOnce(const sim::World& world, const mapping::RunConfig& config);
report::RunResult runOnce(const sim::Site& site, const mapping::RunConfig& config);

using Progress = std::function<void(size_t done, size_t total, const std::string& id)>;

// Every scenario of the suite, seeds 1..seeds each (the same seed list for every scenario).
// `progress` is called before each run with the runs done so far and the total; runs that met the grid's edge
// are added to `gridFull` (when given).
report::ExperimentTable runSuite(const Suite& suite, mapping::Strategy strategy, const std::string& noiseName,
                                 int seeds, const Progress& progress = {}, size_t doneBefore = 0, size_t total = 0);
report::ExperimentTable runSuite(const Suite& suite, const SuiteSettings& settings, const Progress& progress = {},
                                 size_t doneBefore = 0, size_t total = 0, std::vector<GridFullRun>* gridFull = nullptr);

}  // namespace nxtmap::cli
