// Console's goals: a cell to drive to, a cell next to a label, and the labels themselves; each checked against
// the map the console holds before anything is sent.
#include "host/console/Console.hpp"
#include "host/console/GoalDriver.hpp"

namespace nxtmap::console {
namespace {

std::string cellArgs(const ConsoleCommand& c) {
  return "(" + std::to_string(c.col) + "," + std::to_string(c.row) + ")";
}

}  // namespace

std::string Console::startGoal(Cell target, const std::string& what) {
  const std::vector<Cell> path = goals_.planRoute(target, what);
  route_.cancel();
  return goals_.startPath(path, what);
}

std::string Console::gotoCell(const ConsoleCommand& c) {
  const MapView v = goals_.view();
  const std::string what = "goto " + cellArgs(c);
  if (v.bounds.empty() || !v.map.inside(c.col, c.row)) {
    throw ConsoleError(what + ": outside the map (" + std::to_string(v.map.width()) + " x " +
                       std::to_string(v.map.height()) + " cells); nothing sent");
  }
  const mapio::Occupancy o = v.map.at(c.col, c.row);
  if (o == mapio::Occupancy::Occupied) throw ConsoleError(what + ": that cell is an obstacle; nothing sent");
  if (o == mapio::Occupancy::Unknown) throw ConsoleError(what + ": that cell is unexplored; nothing sent");
  return startGoal(v.toCell(c.col, c.row), what);
}

std::string Console::gotoNear(const ConsoleCommand& c) {
  const auto it = house_.labels().find(c.name);
  if (it == house_.labels().end())
    throw ConsoleError("goto near " + c.name + ": no such label (see label NAME C R); nothing sent");
  const MapView v = goals_.view();
  int col = 0, row = 0;
  if (!v.toMap(it->second, col, row) || !v.robot)
    throw ConsoleError("goto near " + c.name + ": the label is outside the map; nothing sent");
  const std::optional<Cell> best = nearestReachableNeighbour(v, col, row);
  if (!best) throw ConsoleError("goto near " + c.name + ": no reachable free cell next to it; nothing sent");
  return startGoal(*best, "near " + c.name);
}

std::string Console::label(const ConsoleCommand& c) {
  if (!mapio::OccupancyMap::validLabelName(c.name))
    throw ConsoleError("label " + c.name + ": a name is 1..64 letters, digits, _ or -, starting with a letter");
  const MapView v = goals_.view();
  if (v.bounds.empty() || !v.map.inside(c.col, c.row))
    throw ConsoleError("label " + c.name + ": the cell is outside the map");
  house_.labels()[c.name] = v.toCell(c.col, c.row);
  return "label " + c.name + " at " + cellArgs(c) + "\n";
}

}  // namespace nxtmap::console
