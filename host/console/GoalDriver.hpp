// GoalDriver: drives the robot to one goal cell of the current room. The route is planned on the
// console's map (MapView, A*) and sent in pieces of at most kSegmentCells cells; when the brick reports
// the way blocked (or the path aborted) the blocked cell is marked and the route replanned, 8 times at
// most. The outcome ("reached", "unreachable: ...") stays readable after the drive ends.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "host/console/MapView.hpp"
#include "host/link/LinkRunner.hpp"

namespace nxtmap::console {

class GoalDriver {
 public:
  static constexpr size_t kSegmentCells = 32;
  static constexpr int kMaxReplans = 8;
  explicit GoalDriver(link::LinkRunner& runner) : runner_(runner) {}

  // The route from the robot to `target` (room frame), the robot's cell first; throws ConsoleError
  // "<what>: <why>; nothing sent" when there is none.
  std::vector<Cell> planRoute(Cell target, const std::string& what) const;
  // Drives a route already planned (path[0] is the robot's cell). Returns what to print.
  std::string startPath(const std::vector<Cell>& path, const std::string& what);
  // Follows the brick's progress: next segment, replanning. Returns a line to print or "".
  std::string poll();

  bool active() const { return active_; }
  const std::string& outcome() const { return outcome_; }
  size_t routeCells() const { return path_.size(); }  // the whole remaining route
  // Stops following (the outcome is kept, or replaced when `outcome` is given).
  void cancel() { active_ = false; }
  void giveUp(const std::string& outcome) {
    active_ = false;
    outcome_ = outcome;
  }

  // The current room's map with the cells reported blocked as obstacles.
  MapView view() const;
  // A new room: the blocked cells were in the old room's frame.
  void clearBlocked() { blocked_.clear(); }

 private:
  std::vector<Cell> planTo(Cell target, std::string& why) const;
  void sendSegment();
  std::string replan(const protocol::PathProgressMsg& p);

  link::LinkRunner& runner_;
  std::set<std::pair<int, int>> blocked_;  // cells the brick reported blocked (current room's frame)
  Cell target_{};
  uint16_t pathId_ = 0;
  uint16_t nextPathId_ = 1;
  std::vector<Cell> path_;  // whole remaining route
  size_t sentUpTo_ = 0;     // index in path_ of the current segment's last cell
  int replans_ = 0;
  bool active_ = false;
  std::string outcome_;  // "reached", "unreachable: ..."; "" before the first goal
};

// The free cell next to (col, row) of `v` (8 neighbours) with the shortest route from the robot.
std::optional<Cell> nearestReachableNeighbour(const MapView& v, int col, int row);

}  // namespace nxtmap::console
