// ExperimentRunner: loads a scenario table with its worlds and runs it for one strategy.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "host/mapping/MappingRun.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::cli {

struct Suite {
  std::string tsvPath;
  std::vector<report::Scenario> scenarios;
  std::map<std::string, sim::World> worlds;  // by Scenario::mapPath
  const sim::World& world(const report::Scenario& s) const { return worlds.at(s.mapPath); }
};

// DIR/scenarios.tsv (or the .tsv file itself) and every world it names; each start is checked.
// Throws CliError naming the file (and line) on any problem.
Suite loadSuite(const std::string& dirOrTsv);

// The published set-up for a scenario: 1 m range, initial heading N.
mapping::RunConfig scenarioConfig(const report::Scenario& s, mapping::Strategy strategy,
                                  const sim::NoiseProfile& noise, uint64_t seed);

// The figures of a finished run.
report::RunResult resultOf(const mapping::MappingRun& run);
// One full run.
report::RunResult runOnce(const sim::World& world, const mapping::RunConfig& config);

using Progress = std::function<void(size_t done, size_t total, const std::string& id)>;

// Every scenario of the suite, seeds 1..seeds each (the same seed list for every scenario).
// `progress` is called before each run with the runs done so far and the total.
report::ExperimentTable runSuite(const Suite& suite, mapping::Strategy strategy, const std::string& noiseName,
                                 int seeds, const Progress& progress = {}, size_t doneBefore = 0,
                                 size_t total = 0);

}  // namespace nxtmap::cli
