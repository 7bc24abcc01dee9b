// Console: carries out console commands against a running link: the map the PC holds (shown
// with the robot), goals planned on it with host/plan and sent as paths (in pieces of at most
// kSegmentCells cells, replanned when the brick reports "blocked"), labels, save and export.
// A bad goal (outside the map, an obstacle, unexplored, unreachable) is refused with one clear
// message and nothing is sent.
#pragma once
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "host/console/ConsoleCommand.hpp"
#include "host/link/LinkRunner.hpp"
#include "host/mapio/OccupancyMap.hpp"
#include "host/plan/Traversability.hpp"

namespace nxtmap::console {

// The PC's map as an OccupancyMap over the known cells' bounding box: column = x - minX,
// row = maxY - y (row grows down, +y is the robot's initial forward).
struct MapView {
  mapio::OccupancyMap map;
  Bounds bounds;
  std::optional<plan::MapCell> robot;  // when the pose is known and inside
  Dir heading = Dir::North;
  bool toMap(Cell c, int& col, int& row) const;
  Cell toCell(int col, int row) const;
};
MapView viewOf(const link::Session& session, const std::set<std::pair<int, int>>& blocked = {});

class Console {
 public:
  static constexpr size_t kSegmentCells = 32;
  explicit Console(link::LinkRunner& runner, std::string linkText);

  // Carries out one command; returns what to print. Throws ConsoleError for a refused command
  // (nothing was sent). Quit returns "" and sets quit().
  std::string execute(const ConsoleCommand& c);
  // Follows the current goal (next segment, replanning); call often. Returns a line to print or "".
  std::string poll();
  bool quit() const { return quit_; }
  std::string renderMap() const;
  std::string statusLine() const;
  // Called about every 20 ms while a command waits (wait explored/goal), e.g. to redraw a live map.
  void onWaiting(std::function<void()> f) { waiting_ = std::move(f); }

 private:
  struct Goal {
    Cell target{};
    uint16_t pathId = 0;
    std::vector<Cell> path;  // whole remaining route
    size_t sentUpTo = 0;     // index in path of the current segment's last cell
    int replans = 0;
    bool active = false;
    std::string outcome;     // "reached", "unreachable: ..."
  };
  std::string startGoal(Cell target, const std::string& what);
  std::vector<Cell> planTo(Cell target, std::string& why) const;
  void sendSegment();
  bool waitFor(const std::function<bool()>& done, double seconds);
  std::function<void()> waiting_;

  link::LinkRunner& runner_;
  std::string linkText_;
  std::map<std::string, Cell> labels_;   // explorer-frame cells
  std::set<std::pair<int, int>> blocked_;  // cells the brick reported blocked (explorer frame)
  Goal goal_;
  uint16_t nextPathId_ = 1;
  bool quit_ = false;
};

}  // namespace nxtmap::console
