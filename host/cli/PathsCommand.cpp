#include "host/cli/PathsCommand.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/OutputTarget.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/plan/MovingAiScenario.hpp"
#include "host/plan/ScenarioCheck.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::cli {
namespace {

constexpr size_t kListedMismatches = 10;

std::string cellText(plan::MapCell c) { return std::to_string(c.col) + "," + std::to_string(c.row); }

}  // namespace

CLI::App* addPathsCommand(CLI::App& app, PathsOptions& o) {
  CLI::App* c = app.add_subcommand("paths", "every Moving AI problem of a .scen file, checked against its optimum");
  c->add_option("map", o.map, "map: Moving AI .map (or a ROS .yaml)")->required();
  c->add_option("--scen", o.scen, "Moving AI scenario file (.scen, version 1)")->required();
  c->add_option("--algo", o.algo, "seed, astar, jps, jps+ or dijkstra (default astar)");
  c->add_option("--csv", o.csv, "write one line per problem as CSV");
  c->add_option("--max-nodes", o.maxNodes,
                "per problem: give up after this many expanded nodes, 1..10^12 (default: no limit)")
      ->check(maxNodesProblem);
  return c;
}

int runPaths(const PathsOptions& o) {
  const auto algorithm = plan::algorithmByName(o.algo);
  if (!algorithm) throw CliError("--algo must be one of seed, astar, jps, jps+, dijkstra, not '" + o.algo + "'");
  const mapio::MapLoad load = mapio::loadMap(o.map);
  if (!load.map) throw CliError(load.error);
  const mapio::OccupancyMap& map = *load.map;
  const plan::ScenarioLoad scen = plan::loadScenario(o.scen);
  if (!scen.problems) throw CliError(scen.error);
  const std::vector<plan::ScenarioProblem>& problems = *scen.problems;
  if (problems.empty()) throw CliError(o.scen + ": no problems in the file");
  for (size_t i = 0; i < problems.size(); ++i) {
    const plan::ScenarioProblem& p = problems[i];
    const std::string where = o.scen + ": problem " + std::to_string(i + 1) + " ";
    if (p.mapWidth != map.width() || p.mapHeight != map.height()) {
      throw CliError(where + "is for a " + std::to_string(p.mapWidth) + "x" + std::to_string(p.mapHeight) +
                     " map, but " + o.map + " is " + std::to_string(map.width()) + "x" + std::to_string(map.height()));
    }
    for (const plan::MapCell& c : {p.start, p.goal}) {
      if (!map.inside(c.col, c.row)) throw CliError(where + "has cell " + cellText(c) + " outside the map");
    }
  }
  std::string csvError;
  if (!o.csv.empty() && !fileio::resolveOutputTarget(o.csv, csvError)) throw CliError(csvError);  // before the runs

  plan::PlanOptions options;
  options.maxNodes = o.maxNodes;
  const plan::Traversability grid(map);
  auto planner = plan::makePlanner(*algorithm);
  const std::vector<plan::ProblemOutcome> out = plan::runProblems(*planner, grid, problems, options);

  size_t matched = 0;
  std::vector<double> micros, nodes;
  std::vector<size_t> mismatches;
  double total = 0, worstGap = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    micros.push_back(out[i].micros);
    nodes.push_back(static_cast<double>(out[i].nodes));
    total += out[i].micros;
    if (out[i].matches) {
      ++matched;
    } else {
      mismatches.push_back(i);
    }
    if (out[i].status == plan::PlanStatus::Found) {
      worstGap = std::max(worstGap, out[i].length - problems[i].optimal);
    }
  }
  if (!o.csv.empty()) {
    std::ostringstream csv;
    csv << "index,bucket,start_col,start_row,goal_col,goal_row,optimal,length,status,nodes,micros,match\n";
    for (size_t i = 0; i < out.size(); ++i) {
      const plan::ScenarioProblem& p = problems[i];
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.8f,%.8f", p.optimal, out[i].length);
      csv << i + 1 << ',' << p.bucket << ',' << p.start.col << ',' << p.start.row << ',' << p.goal.col << ','
          << p.goal.row << ',' << buf << ',' << plan::statusName(out[i].status) << ',' << out[i].nodes << ','
          << report::formatNumber(out[i].micros, 1) << ',' << (out[i].matches ? 1 : 0) << '\n';
    }
    if (!fileio::writeFileAtomically(o.csv, csv.str(), csvError)) throw CliError(csvError);
  }

  std::ostringstream s;
  const std::string mapName = std::filesystem::path(o.map).filename().string();
  s << "map              " << mapName << " " << map.width() << "x" << map.height() << "\n"
    << "scenario         " << std::filesystem::path(o.scen).filename().string() << ": " << problems.size()
    << " problems, buckets " << problems.front().bucket << ".." << problems.back().bucket << "\n";
  if (std::filesystem::path(problems.front().map).filename().string() != mapName) {
    s << "note             the scenario names map '" << problems.front().map << "'\n";
  }
  s << "algorithm        " << plan::algorithmName(*algorithm) << "\n"
    << "matched          " << matched << " of " << problems.size() << " published optima (within "
    << plan::kScenarioTolerance << ")\n";
  if (*algorithm == plan::Algorithm::Seed) {
    s << "longest detour   " << report::formatNumber(worstGap, 3) << " cells over the optimum\n";
  }
  s << "time             median " << report::formatNumber(plan::median(micros) / 1000.0, 3) << " ms, total "
    << report::formatNumber(total / 1000.0, 1) << " ms\n"
    << "nodes expanded   median " << report::formatNumber(plan::median(nodes), 0) << "\n";
  for (size_t k = 0; k < mismatches.size() && k < kListedMismatches; ++k) {
    const size_t i = mismatches[k];
    s << "mismatch         problem " << i + 1 << " (bucket " << problems[i].bucket << ") "
      << cellText(problems[i].start) << " -> " << cellText(problems[i].goal) << ": "
      << (out[i].status == plan::PlanStatus::Found ? "length " + report::formatNumber(out[i].length, 5)
                                                   : std::string(plan::statusName(out[i].status)))
      << ", published " << report::formatNumber(problems[i].optimal, 5) << "\n";
  }
  if (mismatches.size() > kListedMismatches)
    s << "                 ... " << mismatches.size() - kListedMismatches << " more\n";
  if (!o.csv.empty()) s << "wrote            " << o.csv << "\n";
  std::cout << s.str() << std::flush;
  return mismatches.empty() ? kExitOk : 1;
}

}  // namespace nxtmap::cli
