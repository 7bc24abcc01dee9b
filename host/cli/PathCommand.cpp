#include "host/cli/PathCommand.hpp"
#include "host/cli/HousePathCommand.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <sstream>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/plan/NearGoal.hpp"
#include "host/plan/Planner.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::cli {
namespace {

constexpr int kAutoDrawSide = 200;  // --draw auto draws maps up to this many cells a side

std::string cellText(plan::MapCell c) { return std::to_string(c.col) + "," + std::to_string(c.row); }

std::string labelNames(const mapio::OccupancyMap& map) {
  std::vector<std::string> names;
  for (const auto& entry : map.labels()) names.push_back(entry.first);
  return names.empty() ? "the map has no labels; add one with --label NAME=C,R" : "labels: " + joinNames(names);
}

// "NAME=C,R" or "NAME=C,R,W,H" added to the map.
void addLabel(mapio::OccupancyMap& map, const std::string& text) {
  const auto eq = text.find('=');
  const std::string usage = "--label must be NAME=COL,ROW or NAME=COL,ROW,WIDTH,HEIGHT, not '" + text + "'";
  if (eq == std::string::npos) throw CliError(usage);
  const std::string name = text.substr(0, eq);
  std::vector<int> v;
  std::stringstream in(text.substr(eq + 1));
  for (std::string part; std::getline(in, part, ',');) {
    try {
      size_t used = 0;
      v.push_back(std::stoi(part, &used));
      if (used != part.size()) throw CliError(usage);
    } catch (const std::logic_error&) {
      throw CliError(usage);
    }
  }
  if (v.size() != 2 && v.size() != 4) throw CliError(usage);
  const mapio::CellBlock block{v[0], v[1], v.size() == 4 ? v[2] : 1, v.size() == 4 ? v[3] : 1};
  if (!mapio::OccupancyMap::validLabelName(name)) {
    throw CliError("--label name '" + name + "' is not valid (a letter, then letters, digits, '_' or '-')");
  }
  if (!map.setLabel(name, block)) {
    throw CliError("--label " + name + " lies outside the " + std::to_string(map.width()) + "x" +
                   std::to_string(map.height()) + " map");
  }
}

// Why `cell` cannot be an end of a path, or "" if it can.
std::string endProblem(const mapio::OccupancyMap& map, const plan::Traversability& grid, plan::MapCell cell,
                       const plan::PlanOptions& o) {
  if (!map.inside(cell.col, cell.row)) {
    return "lies outside the " + std::to_string(map.width()) + "x" + std::to_string(map.height()) + " map (cols 0.." +
           std::to_string(map.width() - 1) + ", rows 0.." + std::to_string(map.height() - 1) + ")";
  }
  const mapio::Occupancy s = map.at(cell.col, cell.row);
  if (s == mapio::Occupancy::Occupied) return "is an occupied cell";
  if (s == mapio::Occupancy::Unknown && !o.unknownTraversable) {
    return "is an unknown cell (unknown cells are not used unless --through-unknown)";
  }
  if (!grid.passable(cell)) return "is closer to an obstacle than --clearance " + std::to_string(o.clearanceCells);
  return "";
}

std::string drawMap(const mapio::OccupancyMap& map, const plan::PlanResult& r, const mapio::CellBlock* target) {
  std::vector<std::string> rows(static_cast<size_t>(map.height()), std::string(static_cast<size_t>(map.width()), ' '));
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      char ch = '.';
      if (map.at(x, y) == mapio::Occupancy::Occupied) ch = '#';
      if (map.at(x, y) == mapio::Occupancy::Unknown) ch = '~';
      if (target && target->contains(x, y)) ch = 'L';
      rows[static_cast<size_t>(y)][static_cast<size_t>(x)] = ch;
    }
  }
  for (const plan::MapCell& c : r.path) rows[static_cast<size_t>(c.row)][static_cast<size_t>(c.col)] = '*';
  rows[static_cast<size_t>(r.path.front().row)][static_cast<size_t>(r.path.front().col)] = 'S';
  rows[static_cast<size_t>(r.path.back().row)][static_cast<size_t>(r.path.back().col)] = 'G';
  std::string out;
  for (const std::string& row : rows) out += row + "\n";
  out += "(# occupied, . free, ~ unknown, L label, S start, G goal, * path)\n";
  return out;
}

}  // namespace

CLI::App* addPathCommand(CLI::App& app, PathOptions& o) {
  CLI::App* c = app.add_subcommand("path", "one path on a map, drawn, with its length and nodes expanded");
  c->add_option("map", o.map, "map: a world (.map, .yaml) or a map saved by 'nxtmap sim --save'");
  c->add_option("--house", o.house,
                "route across the rooms of a house directory instead (--from ROOM:C,R "
                "--to ROOM:C,R|near:LABEL, cells of the room's map)");
  c->add_option("--from", o.from, "start cell COL,ROW (col right, row down from the top-left)")->required();
  c->add_option("--to", o.to, "goal cell COL,ROW, or near:LABEL (closest reachable cell next to a label)")->required();
  c->add_option("--algo", o.algo,
                "seed (the published search), astar, jps, jps+ (precomputed jumps) or dijkstra (default astar)");
  c->add_option("--label", o.labels, "add a label NAME=COL,ROW or NAME=COL,ROW,WIDTH,HEIGHT (repeatable)");
  c->add_option("--clearance", o.clearance, "keep this many cells away from obstacles (default 0)");
  c->add_flag("--through-unknown", o.throughUnknown, "allow unknown cells (default: never used)");
  c->add_option("--draw", o.draw, "draw the map with the path: auto (up to 200 cells a side), always, never");
  c->add_option("--max-nodes", o.maxNodes, "give up after this many expanded nodes, 1..10^12 (default: no limit)")
      ->check(maxNodesProblem);
  return c;
}

int runPath(const PathOptions& o) {
  if (!o.house.empty()) return runHousePath(o);
  if (o.map.empty()) throw CliError("path: give a MAP, or --house DIR");
  const auto algorithm = plan::algorithmByName(o.algo);
  if (!algorithm) throw CliError("--algo must be one of seed, astar, jps, jps+, dijkstra, not '" + o.algo + "'");
  if (o.draw != "auto" && o.draw != "always" && o.draw != "never") {
    throw CliError("--draw must be one of auto, always, never, not '" + o.draw + "'");
  }
  if (o.clearance < 0 || o.clearance > plan::Traversability::kMaxClearance) {
    throw CliError("--clearance must lie in 0.." + std::to_string(plan::Traversability::kMaxClearance) + ", not " +
                   std::to_string(o.clearance));
  }
  const CellArg fromArg = parseCell(o.from, "--from");
  const bool near = o.to.rfind("near:", 0) == 0;
  CellArg toArg;
  if (!near) toArg = parseCell(o.to, "--to");

  mapio::MapLoad load = mapio::loadMap(o.map);
  if (!load.map) throw CliError(load.error);
  mapio::OccupancyMap& map = *load.map;
  for (const std::string& l : o.labels) addLabel(map, l);

  plan::PlanOptions options;
  options.unknownTraversable = o.throughUnknown;
  options.clearanceCells = o.clearance;
  options.maxNodes = o.maxNodes;
  const plan::Traversability grid(map, options.unknownTraversable, options.clearanceCells);
  const plan::MapCell from{fromArg.col, fromArg.row};
  if (const std::string why = endProblem(map, grid, from, options); !why.empty()) {
    throw CliError("--from " + cellText(from) + " " + why);
  }
  plan::MapCell to{toArg.col, toArg.row};
  const mapio::CellBlock* target = nullptr;
  std::string goalNote;
  if (near) {
    const std::string label = o.to.substr(5);
    const auto it = map.labels().find(label);
    if (it == map.labels().end()) throw CliError("--to: unknown label '" + label + "' (" + labelNames(map) + ")");
    target = &it->second;
    const auto cell = plan::nearestCellNextTo(grid, from, it->second);
    if (!cell) throw CliError("--to near:" + label + ": no usable cell next to it is reachable from " + cellText(from));
    to = *cell;
    goalNote = " (next to " + label + ")";
  } else if (const std::string why = endProblem(map, grid, to, options); !why.empty()) {
    throw CliError("--to " + cellText(to) + " " + why);
  }

  auto planner = plan::makePlanner(*algorithm);
  const plan::PlanResult r = planner->plan(grid, from, to, options);
  if (r.status == plan::PlanStatus::NoPath) {
    throw CliError("no path from " + cellText(from) + " to " + cellText(to) + ": the goal is not reachable" +
                   (o.throughUnknown ? "" : " through known free cells"));
  }
  if (r.status == plan::PlanStatus::NodeLimit) {
    throw CliError("the search stopped at --max-nodes " + std::to_string(o.maxNodes) + " before reaching the goal");
  }
  if (!r.found()) throw CliError(std::string("cannot plan: ") + plan::statusName(r.status));

  const bool draw =
      o.draw == "always" || (o.draw == "auto" && map.width() <= kAutoDrawSide && map.height() <= kAutoDrawSide);
  std::ostringstream out;
  if (draw) out << drawMap(map, r, target) << "\n";
  int diagonal = 0;
  for (size_t i = 1; i < r.path.size(); ++i) {
    if (r.path[i].col != r.path[i - 1].col && r.path[i].row != r.path[i - 1].row) ++diagonal;
  }
  const int moves = static_cast<int>(r.path.size()) - 1;
  out << "algorithm        " << plan::algorithmName(*algorithm) << "\n"
      << "from             " << cellText(from) << "\n"
      << "to               " << cellText(to) << goalNote << "\n"
      << "length           " << report::formatNumber(r.length, 3) << " cells ("
      << report::formatNumber(r.length * map.resolutionM(), 2) << " m)\n"
      << "moves            " << moves << " (" << moves - diagonal << " straight, " << diagonal << " diagonal)\n"
      << "nodes expanded   " << r.nodesExpanded << "\n";
  std::cout << out.str() << std::flush;
  return kExitOk;
}

}  // namespace nxtmap::cli
