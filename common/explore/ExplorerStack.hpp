// ExplorerStack: the one assembly of an explorer, used wherever one runs (the brick, the stand-in
// brick, the simulator's room and house runs). It holds the map layers and the travel planner over
// caller-owned memory, the run's strategy (one of the explorers, built in place when a run starts)
// and the pilot that keeps the robot on the grid. Events in (DriveEvent), actions out (DriveAction).
// A new strategy is added here only: a member of Strategy, an alternative of the variant, a case
// in start().
#pragma once
#include <cstdint>
#include <optional>
#include <variant>

#include "common/explore/ExplorerConfig.hpp"
#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/explore/GoToExplorer.hpp"
#include "common/explore/PropagationExplorer.hpp"
#include "common/motion/Pilot.hpp"

namespace nxtmap {

// What a run does: map with the published method, map by frontiers, or drive to one cell over the
// map as it is (travel between rooms, with the pilot's pose corrections on the way).
enum class Strategy : uint8_t { Propagation, Frontier, GoTo };

class ExplorerStack {
 public:
  // Memory of a capacity: ExplorerStorage<W, H, Q>::memory() on the brick, a host buffer on the PC.
  ExplorerStack(const ExplorerMemory& memory, const ExplorerConfig& config);
  ExplorerStack(const ExplorerStack&) = delete;
  ExplorerStack& operator=(const ExplorerStack&) = delete;

  // Starts a run of `strategy` on the map as it is, the robot at `at` (a new room: Pose{}); for
  // GoTo, `target` is the cell to reach; `shut`: cells held closed that are no walls (see
  // Pilot::setVirtualWalls; must outlive the run). Any run before is dropped. Returns the first action.
  DriveAction start(Strategy strategy, const PilotConfig& pilot, const Pose& at = Pose{}, Cell target = Cell{},
                    const CellSet* shut = nullptr);
  // Feeds one event of the running run and returns what to do next (Done once it is over).
  DriveAction step(const DriveEvent& e);
  // Drops the run (the map stays): the explorer and its pilot are gone.
  void end();

  bool running() const { return pilot_.has_value(); }
  bool finished() const { return pilot_.has_value() && pilot_->finished(); }
  Strategy strategy() const { return strategy_; }

  MapLayers& map() { return map_; }
  const MapLayers& map() const { return map_; }
  TravelPlanner& planner() { return planner_; }
  const ExplorerConfig& config() const { return config_; }
  void setConfig(const ExplorerConfig& config) { config_ = config; }

  // The running run's explorer and pilot (nullptr when no run).
  Explorer* explorer();
  const Explorer* explorer() const;
  Pilot* pilot() { return pilot_ ? &*pilot_ : nullptr; }
  // Where the running pilot believes the robot's centre is from its explorer's cell's centre (mm, x east, y
  // north, PoseTracker), once its explorer has started; false (and 0, 0) otherwise.
  bool believedOffset(int32_t& xMm, int32_t& yMm) const;
  const Pilot* pilot() const { return pilot_ ? &*pilot_ : nullptr; }
  const PropagationExplorer* propagation() const { return std::get_if<PropagationExplorer>(&explorer_); }
  const GoToExplorer* goTo() const { return std::get_if<GoToExplorer>(&explorer_); }
  // The run's counters (zero without a run).
  Counters counters() const { return pilot_ ? pilot_->counters() : Counters{}; }

 private:
  MapLayers map_;
  TravelPlanner planner_;
  ExplorerConfig config_;
  Strategy strategy_ = Strategy::Frontier;
  std::variant<std::monostate, PropagationExplorer, FrontierExplorer, GoToExplorer> explorer_;
  std::optional<Pilot> pilot_;
};

}  // namespace nxtmap
