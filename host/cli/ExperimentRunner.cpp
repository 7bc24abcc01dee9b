#include "host/cli/ExperimentRunner.hpp"

#include <filesystem>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/mapping/MapScore.hpp"
#include "host/mapping/PoseErrorShare.hpp"

namespace nxtmap::cli {

Suite loadSuite(const std::string& dirOrTsv, int cellCm) {
  namespace fs = std::filesystem;
  std::error_code ec;
  Suite suite;
  suite.cellCm = cellCm;
  if (fs::is_directory(dirOrTsv, ec)) {
    suite.tsvPath = (fs::path(dirOrTsv) / "scenarios.tsv").string();
    if (!fs::exists(suite.tsvPath, ec)) throw CliError(dirOrTsv + ": no scenarios.tsv in this directory");
  } else if (fs::is_regular_file(dirOrTsv, ec)) {
    suite.tsvPath = dirOrTsv;
  } else {
    throw CliError(dirOrTsv + ": no such directory");
  }
  report::ScenarioLoad load = report::loadScenarios(suite.tsvPath);
  if (!load.error.empty()) throw CliError(load.error);
  suite.scenarios = std::move(load.scenarios);
  for (const report::Scenario& s : suite.scenarios) {
    const std::string where = suite.tsvPath + " line " + std::to_string(s.line) + ": ";
    auto it = suite.worlds.find(s.mapPath);
    if (it == suite.worlds.end()) {
      sim::WorldLoad w = fs::path(s.mapPath).extension() == ".map" ? sim::World::loadMovingAi(s.mapPath, cellCm / 100.0)
                                                                   : sim::World::load(s.mapPath);
      if (!w.world) throw CliError(where + w.error);
      it = suite.worlds.emplace(s.mapPath, std::move(*w.world)).first;
      suite.sites.emplace(s.mapPath, sim::siteFromRaster(it->second));
    }
    checkStart(it->second, s.startCol, s.startRow, where);
  }
  return suite;
}

mapping::RunConfig scenarioConfig(const report::Scenario& s, mapping::Strategy strategy, const sim::NoiseProfile& noise,
                                  uint64_t seed) {
  mapping::RunConfig c;
  c.startCol = s.startCol;
  c.startRow = s.startRow;
  c.heading = sim::Heading::N;
  c.rangeM = 1.0;
  c.noise = noise;
  c.seed = seed;
  c.strategy = strategy;
  return c;
}

namespace {
report::RunResult resultOf(const mapping::MappingRun& run, const mapping::PoseErrorShare& pose) {
  const mapping::MapScore s = mapping::scoreRun(run);
  const Counters c = run.counters();
  report::RunResult r;
  r.actualFree = s.actualFree;
  r.foundFree = s.foundFree;
  r.actualOccupied = s.actualOccupied;
  r.foundOccupied = s.foundOccupied;
  r.unknown = s.unknown;
  r.unknownObservable = s.unknownObservable;
  r.wrongCells = s.wrongCells;
  r.detectedPct = s.detectedPct();
  r.performancePct = s.seedPerformancePct();
  r.timeUnits = c.timeHalfUnits() / 2.0;
  r.sensorReads = c.sensorRequests;
  r.roomCells = static_cast<double>(run.world().width()) * run.world().height();
  r.complete = run.explorer().end() == ExplorerEnd::Complete;
  r.unsafeFree = s.unsafeFree;
  r.phantomOccupied = s.phantomOccupied;
  r.lost = s.lost ? 1.0 : 0.0;
  r.detectedPctAligned = s.detectedPctAligned();
  r.wrongCellsAligned = s.wrongCellsAligned;
  r.headingOffPct = pose.headingOffPct();
  r.positionOffPct = pose.positionOffPct();
  if (const std::optional<double> turned = run.squaredTurnedDeg()) {
    r.squared = true;
    r.squaredDeg = *turned;
  }
  return r;
}
}  // namespace

report::RunResult runAndScore(mapping::MappingRun& run) {
  mapping::PoseErrorShare pose;
  while (run.step()) pose.add(run);
  pose.add(run);
  return resultOf(run, pose);
}

report::RunResult runAndScore(mapping::MappingRun& run, const std::string& id, std::vector<GridFullRun>* gridFull) {
  const report::RunResult r = runAndScore(run);
  if (gridFull && run.metGridEdge()) {
    gridFull->push_back(
        GridFullRun{id, static_cast<int>(run.config().seed), run.world().width(), run.world().height()});
  }
  return r;
}

mapping::RunConfig scenarioConfig(const report::Scenario& s, const SuiteSettings& settings, uint64_t seed) {
  mapping::RunConfig c = scenarioConfig(s, settings.strategy, parseNoise(settings.noise), seed);
  c.robot = settings.robot;
  c.startJitterDeg = settings.startJitterDeg;
  c.squareAtStart = settings.squareAtStart;
  c.calibrateTurns = settings.calibrateTurns;
  c.calibrateUnknownTurns = settings.calibrateUnknownTurns;
  c.grid = settings.grid;
  return c;
}

report::RunResult runOnce(const sim::Site& site, const mapping::RunConfig& config) {
  mapping::MappingRun run(site, config);
  return runAndScore(run);
}

report::RunResult runOnce(const sim::World& world, const mapping::RunConfig& config) {
  mapping::MappingRun run(world, config);
  return runAndScore(run);
}

WheelCalibration firstOutingWheels(const Suite& suite, size_t scenario, const SuiteSettings& settings, uint64_t seed) {
  const report::Scenario& s = suite.scenarios[scenario];
  mapping::MappingRun run(suite.site(s), scenarioConfig(s, settings, seed));
  run.runToEnd();
  return run.pilot().wheels();
}

report::ExperimentTable runSuite(const Suite& suite, mapping::Strategy strategy, const std::string& noiseName,
                                 int seeds, const Progress& progress, size_t doneBefore, size_t total) {
  SuiteSettings settings;
  settings.strategy = strategy;
  settings.noise = noiseName;
  settings.seeds = seeds;
  return runSuite(suite, settings, progress, doneBefore, total);
}

report::ExperimentTable runSuite(const Suite& suite, const SuiteSettings& settings, const Progress& progress,
                                 size_t doneBefore, size_t total, std::vector<GridFullRun>* gridFull) {
  parseNoise(settings.noise);
  report::ExperimentTable table;
  table.strategy = mapping::strategyName(settings.strategy);
  table.noise = settings.noise;
  table.seeds = settings.seeds;
  if (total == 0) total = suite.scenarios.size() * static_cast<size_t>(settings.seeds);
  size_t done = doneBefore;
  for (size_t i = 0; i < suite.scenarios.size(); ++i) {
    const report::Scenario& s = suite.scenarios[i];
    report::ExperimentRow row;
    row.scenario = s;
    for (int seed = 1; seed <= settings.seeds; ++seed) {
      if (progress) progress(done, total, s.id);
      mapping::RunConfig config = scenarioConfig(s, settings, static_cast<uint64_t>(seed));
      if (settings.afterFirstOuting)
        config.storedWheels = firstOutingWheels(suite, (i + 1) % suite.scenarios.size(), settings, config.seed);
      mapping::MappingRun run(suite.site(s), config);
      row.perSeed.push_back(runAndScore(run, s.id, gridFull));
      ++done;
    }
    row.summarize();
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace nxtmap::cli
