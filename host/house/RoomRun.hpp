// RoomRun: one room of a house, mapped by the common explorer and pilot (which keeps the robot on
// the cell grid under noise) driving the shared simulated robot (the robot keeps its true pose
// from room to room), exactly as MappingRun does for a single room. The room's frame has its origin at
// the cell where the run starts and +y along the robot's heading there.
//
// Confinement (until the explorer itself knows about exits, see notes/house-to-lead.md): after
// every event the run looks for doorways near the robot in the map (common/interpret
// findDoorways). A doorway that separates the room's start from what lies beyond it, with the
// robot on the start's side, becomes an exit: its cells are held as walls in the explorer's map
// ("virtual doors") so the explorer maps this room only. The entrance doorway is closed the same
// way from the start. When the explorer is done, the doorways are opened again (free) and the
// map is cut to the room: the cells reachable from the start, their neighbours and the doorways.
#pragma once

#include <memory>
#include <vector>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/explore/PropagationExplorer.hpp"
#include "common/interpret/Doorway.hpp"
#include "common/interpret/RoomInterpretation.hpp"
#include "common/motion/Pilot.hpp"
#include "common/sensing/RangeFilter.hpp"
#include "host/mapping/Strategy.hpp"
#include "host/network/RoomMap.hpp"
#include "host/sim/SimRobot.hpp"

namespace nxtmap::house {

// An exit of a room in the room's frame: the doorway's cells, the cell inside the room in front
// of its middle, and the direction that leads out through it.
struct RoomExit {
  std::vector<Cell> cells;
  Cell inside{};
  Dir outward = Dir::North;
  int16_t depth = 1;  // cells to cross
};

class RoomRun {
 public:
  using Storage = ExplorerStorage<128, 128, 8192>;

  // `entrance`: the doorway's cells behind the start, in the new room's frame (empty for the first room).
  // `pilot`: how the run's pilot keeps the robot on the grid (PilotConfig::correct false: dead
  // reckoning), including the heading uncertainty the robot is handed over with.
  RoomRun(sim::SimRobot& robot, const ExplorerConfig& config, mapping::Strategy strategy, const DoorwayLimits& doorways,
          std::vector<Cell> entrance, const PilotConfig& pilot = PilotConfig{},
          const RoomLimits& roomLimits = RoomLimits{});
  ~RoomRun();

  // Maps the room to the end; then the doorways are open again and exits() / roomMap() are set.
  void runToEnd();

  const Explorer& explorer() const { return *explorer_; }
  Counters counters() const { return pilot_->counters(); }
  // After runToEnd: the heading's variance the robot is handed over with (mrad^2).
  int64_t handOverHeadingVariance() const { return pilot_->handOverHeadingVariance(); }
  ExplorerEnd end() const { return explorer_->end(); }
  const Pose& pose() const { return explorer_->pose(); }  // believed, in the room's frame
  const std::vector<RoomExit>& exits() const { return exits_; }
  const network::RoomMap& roomMap() const { return roomMap_; }
  // Everything the run saw, beyond the exits too (the robot may end there): for travel planning.
  const network::RoomMap& fullMap() const { return fullMap_; }
  // The interpretation of the finished map (walls, size, exits, how many rooms it makes).
  const RoomInterpretation& interpretation() const { return interpretation_; }
  int ignoredDoorways() const { return static_cast<int>(candidates_.size()); }  // never became exits
  // The readings taken where the run started, before the robot first drove or turned, with the
  // direction (room frame) each looked in: the only ones from a pose known exactly (see StartAnchor).
  struct StartReading {
    Dir dir;
    RangeReading reading;
  };
  const std::vector<StartReading>& startReadings() const { return startReadings_; }

 private:
  void closeDoors();  // marks shut_ blocked in the map (after every step)
  void updateShut();  // shut_ from closed_ and guards_, after either changed
  // Closes the entrance's cells and guards the ends of its line (see guards_).
  void closeEntrance();
  bool drivesIntoClosed(const DriveAction& a) const;
  void lookForDoorways();
  void evaluateCandidates();
  bool wellSeen(const Doorway& d) const;
  static constexpr int kSureEvidence = 1;  // |evidence| a doorway's cells need (1: as the three-state map)
  // Cells reachable from the start over free cells, with the given extra cells held closed.
  std::vector<uint8_t> reach(const std::vector<Cell>& closed, Bounds& box) const;
  void finish();

  sim::SimRobot& robot_;
  ExplorerConfig config_;
  DoorwayLimits doorwayLimits_;
  std::unique_ptr<Storage> storage_;
  std::unique_ptr<MapLayers> map_;
  std::unique_ptr<TravelPlanner> planner_;
  std::unique_ptr<PropagationExplorer> propagation_;
  std::unique_ptr<FrontierExplorer> frontier_;
  Explorer* explorer_ = nullptr;
  std::unique_ptr<Pilot> pilot_;
  DriveAction last_;
  bool moved_ = false;  // the robot drove or turned since the run started
  std::vector<StartReading> startReadings_;
  std::vector<Cell> closed_;  // virtual door cells (entrance and exits)
  std::vector<Cell> shut_;    // closed_ and guards_ (held blocked each step), lent to the pilot
  std::vector<Cell> guards_;  // the cells beside the entrance along its line (its jambs), closed too
  std::vector<Cell> entrance_;
  std::vector<RoomExit> exits_;
  std::vector<Doorway> candidates_;  // doorways seen that are not (yet) exits
  int sinceCheck_ = 0;               // steps since the candidates were last evaluated
  static constexpr int kRecheckSteps = 25;
  network::RoomMap fullMap_;
  network::RoomMap roomMap_;
  RoomLimits roomLimits_;
  RoomInterpretation interpretation_;
};

}  // namespace nxtmap::house
