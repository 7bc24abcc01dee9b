#include "host/cli/ExperimentsCommand.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/ExperimentRunner.hpp"
#include "host/cli/ProgressLine.hpp"
#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/report/Plots.hpp"

namespace nxtmap::cli {
namespace {
namespace fs = std::filesystem;

// path with `suffix` before its extension: out.csv + "-frontier" -> out-frontier.csv
std::string withSuffix(const std::string& path, const std::string& suffix) {
  const fs::path p(path);
  return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

// Refuses an output that cannot be written (fileio::OutputTarget) before the runs; nothing is written yet.
void checkOutput(const std::string& path) {
  std::string error;
  if (!fileio::resolveOutputTarget(path, error)) throw CliError(error);
}

// "N of M runs met the edge of the grid (a x2, b x1): the room is larger ..." for the runs that ended GridFull.
std::string gridFullSummary(const std::vector<GridFullRun>& runs, size_t total, const mapping::GridCapacity& grid,
                            int cellCm) {
  std::vector<std::pair<std::string, int>> byScenario;  // runs per scenario, in the order first met
  int cols = 0, rows = 0;
  for (const GridFullRun& r : runs) {
    auto it = std::find_if(byScenario.begin(), byScenario.end(), [&](const auto& s) { return s.first == r.id; });
    if (it == byScenario.end()) it = byScenario.insert(byScenario.end(), {r.id, 0});
    ++it->second;
    cols = std::max(cols, r.roomCols);
    rows = std::max(rows, r.roomRows);
  }
  std::ostringstream o;
  o << "grid full: " << runs.size() << " of " << total << " runs met the grid's edge (";
  for (size_t i = 0; i < byScenario.size(); ++i)
    o << (i > 0 ? ", " : "") << byScenario[i].first << " x" << byScenario[i].second;
  o << "): " << gridFullNote(grid, cellCm, cols, rows);
  return o.str();
}

// Writes `text` to `path` whole or not at all.
void writeOutput(const std::string& path, const std::string& text) {
  std::string error;
  if (!fileio::writeFileAtomically(path, text, error)) throw CliError(error);
  std::cout << "wrote " << path << '\n';
}
}  // namespace

CLI::App* addExperimentsCommand(CLI::App& app, ExperimentsOptions& o) {
  CLI::App* ex = app.add_subcommand("experiments", "every run of DIR/scenarios.tsv beside the published figures");
  ex->add_option("dir", o.dir, "scenario directory holding scenarios.tsv (e.g. worlds/seed-appendix-a)");
  ex->add_option("--csv", o.csv,
                 "write the results as CSV (with --strategy both: FILE-<strategy>.csv; with --seeds N>1 also "
                 "FILE-seeds.csv per run)");
  ex->add_option("--markdown", o.markdown, "write a Markdown report");
  ex->add_option("--plots", o.plots, "write gnuplot figures fig5_3/fig5_4/fig5_6 (.png) into this directory");
  addWorldRunOptions(*ex, o.run);
  addGridOption(*ex, o.run);
  addSquareOption(*ex, o.run);
  ex->add_option("--seeds", o.seeds, "runs per scenario with seeds 1..N, reported as means (default 1)");
  ex->add_option("--strategy", o.strategy, "propagation, frontier or both (default propagation)");
  ex->add_flag("--after-first-outing", o.afterFirstOuting,
               "each robot (seed) first maps the next layout with nothing stored and starts the measured run with "
               "the wheels' errors it learnt there, as the brick keeps them from run to run (twice the runs)");
  return ex;
}

int runExperiments(const ExperimentsOptions& o) {
  if (printNoiseListIfAsked(o.run)) return kExitOk;
  requirePositional(o.dir, "experiments: dir");
  const std::vector<mapping::Strategy> strategies = parseStrategies(o.strategy);
  SuiteSettings settings;
  parseNoise(o.run.noise);
  settings.noise = o.run.noise;
  settings.seeds = o.seeds;
  settings.robot = parseRobot(o.run.robot);
  settings.startJitterDeg = checkStartJitter(o.run.startJitterDeg);
  settings.squareAtStart = squareAtStart(o.run.square, settings.robot);
  const CalibrationChoice calibration = calibrationOf(o.run);
  settings.calibrateTurns = calibration.turns;
  settings.calibrateUnknownTurns = calibration.whenUnknown;
  settings.grid = gridOf(o.run);
  settings.afterFirstOuting = o.afterFirstOuting;
  if (o.seeds < 1 || o.seeds > 1000) throw CliError("--seeds must lie in 1..1000, not " + std::to_string(o.seeds));
  if (!o.plots.empty() && report::findGnuplot().empty()) {
    throw CliError("--plots needs gnuplot, which is not on PATH; install gnuplot or leave out --plots");
  }
  const Suite suite = loadSuite(o.dir, settings.robot.cellCm);

  // Check every output first so a bad path fails before the runs.
  std::vector<std::string> csvs;
  if (!o.csv.empty()) {
    for (mapping::Strategy s : strategies) {
      csvs.push_back(strategies.size() > 1 ? withSuffix(o.csv, "-" + mapping::strategyName(s)) : o.csv);
      checkOutput(csvs.back());
    }
  }
  const std::string seedCsvPath = !o.csv.empty() && o.seeds > 1 ? withSuffix(o.csv, "-seeds") : "";
  if (!seedCsvPath.empty()) checkOutput(seedCsvPath);
  if (!o.markdown.empty()) checkOutput(o.markdown);

  const size_t total = suite.scenarios.size() * static_cast<size_t>(o.seeds) * strategies.size();
  std::vector<report::ExperimentTable> tables;
  std::vector<GridFullRun> gridFull;
  {
    // In a log a few runs go without progress lines.
    const bool tty = stderrIsTerminal();
    std::optional<ProgressLine> line;
    if (tty || total > 36) line.emplace(std::cerr, tty, "experiments", total);
    const Progress progress = [&](size_t, size_t, const std::string& id) {
      if (line) line->tick(1, id);
    };
    size_t done = 0;
    for (mapping::Strategy s : strategies) {
      settings.strategy = s;
      tables.push_back(runSuite(suite, settings, progress, done, total, &gridFull));
      done += suite.scenarios.size() * static_cast<size_t>(o.seeds);
    }
  }

  std::cout << "experiments " << suite.tsvPath << ": " << suite.scenarios.size() << " runs";
  if (o.seeds > 1) std::cout << " x " << o.seeds << " seeds";
  std::cout << ", robot " << settings.robot.name << " (" << settings.robot.cellCm << " cm cells)";
  if (settings.startJitterDeg > 0.0) std::cout << ", set down up to " << settings.startJitterDeg << " deg off square";
  if (!settings.grid.isBrick()) std::cout << ", grid " << settings.grid.describe();
  std::cout << ", published medians " << report::formatNumber(report::kPublishedMedianTimeUnits) << " time units, "
            << report::formatNumber(report::kPublishedMedianSensorReads) << " sensor reads\n";
  for (const report::ExperimentTable& t : tables) {
    std::cout << '\n';
    t.writeConsole(std::cout);
  }
  if (!gridFull.empty())
    std::cout << '\n' << gridFullSummary(gridFull, total, settings.grid, settings.robot.cellCm) << '\n';

  for (size_t i = 0; i < csvs.size(); ++i) {
    std::ostringstream csv;
    tables[i].writeCsv(csv);
    writeOutput(csvs[i], csv.str());
  }
  if (!seedCsvPath.empty()) {
    std::ostringstream seedCsv;
    for (size_t i = 0; i < tables.size(); ++i) tables[i].writeSeedCsv(seedCsv, i == 0);
    writeOutput(seedCsvPath, seedCsv.str());
  }
  if (!o.markdown.empty()) {
    std::ostringstream markdown;
    markdown << "# nxtmap experiments: " << suite.tsvPath << "\n\n"
             << "Ours beside the thesis's published figures (Appendix A). Time in cell units (one per cell "
                "moved and per 90 degree turn); detected % = occupied cells mapped of those observable from "
                "the reachable free space.\n\n";
    for (const report::ExperimentTable& t : tables) {
      t.writeMarkdown(markdown);
      markdown << '\n';
    }
    writeOutput(o.markdown, markdown.str());
  }
  if (!o.plots.empty()) {
    std::vector<std::string> written;
    std::string error;
    if (!report::writePlots(o.plots, tables, written, error)) throw CliError(error);
    for (const std::string& w : written) std::cout << "wrote " << w << '\n';
  }
  return kExitOk;
}

}  // namespace nxtmap::cli
