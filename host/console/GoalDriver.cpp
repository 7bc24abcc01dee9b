#include "host/console/GoalDriver.hpp"

#include <algorithm>
#include <sstream>

#include "host/console/ConsoleCommand.hpp"
#include "host/plan/Planner.hpp"

namespace nxtmap::console {

using protocol::PathState;

MapView GoalDriver::view() const {
  return runner_.with([&](link::Session& s) { return viewOf(s, blocked_); });
}

std::vector<Cell> GoalDriver::planTo(Cell target, std::string& why) const {
  const MapView v = view();
  std::vector<Cell> cells;
  int col = 0, row = 0;
  if (!v.robot) {
    why = "the robot's position is not known yet";
  } else if (!v.toMap(target, col, row)) {
    why = "the goal is outside the map";
  } else {
    const plan::PlanResult r =
        plan::makePlanner(plan::Algorithm::AStar)->plan(v.map, *v.robot, plan::MapCell{col, row});
    if (!r.found()) why = "no known free route from the robot to the goal";
    if (r.found())
      for (const plan::MapCell& m : r.path) cells.push_back(v.toCell(m.col, m.row));
  }
  return cells;
}

void GoalDriver::sendSegment() {
  const size_t from = sentUpTo_;
  const size_t to = std::min(path_.size() - 1, from + kSegmentCells - 1);
  std::vector<Cell> segment(path_.begin() + static_cast<long>(from), path_.begin() + static_cast<long>(to) + 1);
  pathId_ = nextPathId_++;
  sentUpTo_ = to;
  runner_.with([&](link::Session& s) { return s.followPath(segment, pathId_); });
}

std::vector<Cell> GoalDriver::planRoute(Cell target, const std::string& what) const {
  std::string why;
  std::vector<Cell> path = planTo(target, why);
  if (path.empty()) throw ConsoleError(what + ": " + why + "; nothing sent");
  return path;
}

std::string GoalDriver::startPath(const std::vector<Cell>& path, const std::string& what) {
  target_ = path.back();
  path_ = path;
  sentUpTo_ = 0;
  replans_ = 0;
  outcome_.clear();
  active_ = path.size() > 1;
  if (!active_) {
    outcome_ = "reached";
    return "the robot is already there\n";
  }
  sendSegment();
  std::ostringstream o;
  o << "driving to " << what << ": " << path.size() - 1 << " moves\n";
  return o.str();
}

std::string GoalDriver::poll() {
  if (!active_) return "";
  const std::optional<protocol::PathProgressMsg> p = runner_.with([](link::Session& s) { return s.pathProgress(); });
  if (!p || p->pathId != pathId_) return "";
  if (p->state == PathState::Reached) {
    if (sentUpTo_ + 1 < path_.size()) {
      sendSegment();
      return "";
    }
    giveUp("reached");
    return "goal reached\n";
  }
  if (p->state == PathState::Blocked || p->state == PathState::Aborted) return replan(*p);
  return "";
}

std::string GoalDriver::replan(const protocol::PathProgressMsg& p) {
  if (p.state == PathState::Blocked) blocked_.insert({p.at.x, p.at.y});
  if (++replans_ > kMaxReplans) {
    giveUp("unreachable: blocked too often");
    return "goal given up: the way was blocked 8 times\n";
  }
  std::string why;
  const std::vector<Cell> path = planTo(target_, why);
  if (path.empty()) {
    giveUp("unreachable: " + why);
    return "goal given up: " + why + "\n";
  }
  path_ = path;
  sentUpTo_ = 0;
  sendSegment();
  return "blocked at (" + std::to_string(p.at.x) + "," + std::to_string(p.at.y) + "): replanned\n";
}

std::optional<Cell> nearestReachableNeighbour(const MapView& v, int col, int row) {
  if (!v.robot) return std::nullopt;
  auto planner = plan::makePlanner(plan::Algorithm::AStar);
  std::optional<Cell> best;
  double bestLength = 0;
  for (int dr = -1; dr <= 1; ++dr) {
    for (int dc = -1; dc <= 1; ++dc) {
      if ((dr == 0 && dc == 0) || !v.map.isFree(col + dc, row + dr)) continue;
      const plan::PlanResult r = planner->plan(v.map, *v.robot, plan::MapCell{col + dc, row + dr});
      if (r.found() && (!best || r.length < bestLength)) {
        best = v.toCell(col + dc, row + dr);
        bestLength = r.length;
      }
    }
  }
  return best;
}

}  // namespace nxtmap::console
