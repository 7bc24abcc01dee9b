// HouseMapper: maps a house in the simulator room by room (method section 5): map the room
// (RoomRun), record its exits; then pick the nearest unexplored exit, plan to it over what is
// known, pass through, start a new room map with its origin at the entrance, map it and record
// the gateway; repeat until no unexplored exit is left. An exit that leads into a room already
// mapped becomes a gateway to it without a new run. One simulated robot keeps its true pose
// throughout; everything the mapper decides uses only its believed pose and its maps.
#pragma once

#include <cstdint>
#include <vector>

#include "common/explore/Counters.hpp"
#include "common/interpret/Doorway.hpp"
#include "common/interpret/RoomInterpretation.hpp"
#include "host/house/RoomRun.hpp"
#include "host/house/StartAnchor.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/mapping/Strategy.hpp"
#include "host/network/HouseNetwork.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/Site.hpp"
#include "host/sim/World.hpp"

#include <optional>

namespace nxtmap::house {

struct HouseConfig {
  int startCol = 0, startRow = 0;           // start cell in the site's raster (when startPose is empty);
                                            // after construction (config()): in the truth raster
  sim::Heading heading = sim::Heading::N;   // initial heading in the world (= house frame +y)
  std::optional<sim::StartPose> startPose;  // a start in the plane instead of a raster cell
  double startJitterDeg = 0.0;              // > 0: set down off the cell centre and up to this far off square
  // The robot (cells, body, sensor mounts, trusted range: replaces rangeM/minRangeM); empty: a point robot of
  // the raster's own cells (the published set-up).
  std::optional<sim::RobotDescription> robot;
  double rangeM = 1.0, minRangeM = 0.05;  // trusted sensor range (published: 5 cm - 1 m)
  double sensorReachCm = 255.0;
  sim::NoiseProfile noise;
  uint64_t seed = 1;
  mapping::Strategy strategy =
      mapping::Strategy::Frontier;      // fewer turns than the published staircase: the pose holds better
  DoorwayLimits doorways{4, 15, 3, 2};  // cells: 0.4 .. 1.5 m doorways at 10 cm cells, walls of 2+ cells
  RoomLimits roomLimits{3, 80};         // an open area over 8 m (at 10 cm cells) is several rooms
  int maxRooms = 40;                    // safety stop
  bool poseCorrection = true;           // the pilot keeps the robot on the grid (off: dead reckoning)
  int registerCells = 2;                // a new room's frame may shift this far to fit the rooms mapped (0: off)
  int maxOpenings = 6;                  // openings onto unknown space the exits missed, explored at the end (0: none)
  // A robot that drives into a wall the map does not have on the way to an exit, or finds no exit
  // reachable from where it believes it stands, reads all four sides and moves its belief by the
  // whole cells (up to this many each way) that fit the map best, then tries once more (0: off).
  int relocaliseCells = 2;
  // The readings taken at the very start, where the robot surely is, are matched against the
  // finished start room; a whole-cell shift under which they fit again (and do not as mapped) moves
  // the start room's frame and the belief with it (see StartAnchor). false: off.
  bool anchorStart = true;
};

struct HouseCounters {
  Counters explore;            // summed over the room runs
  Counters travel;             // driving between rooms (to exits, through doorways)
  uint32_t travelBlocked = 0;  // travels that did not arrive
  double timeUnits() const { return (explore.timeHalfUnits() + travel.timeHalfUnits()) / 2.0; }
  uint32_t sensorRequests() const { return explore.sensorRequests + travel.sensorRequests; }
};

class HouseMapper {
 public:
  // The robot set down in `site` as the configuration says; the site's scene is shared with the mapper.
  HouseMapper(const sim::Site& site, const HouseConfig& config);
  HouseMapper(const sim::World& world, const HouseConfig& config);

  // Maps the whole house (every exit reachable from the start). Returns the number of rooms.
  int run();

  const network::HouseNetwork& network() const { return network_; }
  network::HouseNetwork& network() { return network_; }
  const HouseCounters& counters() const { return counters_; }
  int exitsFound() const { return exitsFound_; }
  int exitsUnreached() const { return exitsUnreached_; }    // exits the robot could not get through
  int relocalisations() const { return relocalisations_; }  // beliefs moved by a standing scan (see HouseConfig)
  Cell startShift() const {
    return startShift_;
  }  // the start room's frame moved by this (see HouseConfig::anchorStart)
  int openingsTried() const { return static_cast<int>(openingsTried_.size()); }  // see HouseConfig::maxOpenings
  const sim::SimRobot& robot() const { return robot_; }
  const sim::World& world() const { return world_; }
  const HouseConfig& config() const { return config_; }
  const ExplorerConfig& explorerConfig() const { return explorerConfig_; }
  // House frame (room 0: origin at the start, +y the initial heading) <-> world cells.
  const mapping::FrameTransform& houseFrame() const { return frame_; }

 private:
  struct Pending {
    int room;
    RoomExit exit;  // in the room's frame
  };
  void mapRoom(const std::vector<Cell>& entranceHouse, int fromRoom, const RoomExit* via);
  bool leadsToMappedRoom(const Pending& p);
  void mapPendingExits();  // maps rooms through the pending exits, nearest first, until none is reachable
  bool queueOpening();     // an opening onto unmapped space as the next exit (false: none, or the limit)
  // With NXTMAP_HOUSE_DEBUG set: the believed cell against the simulated robot's true position.
  void debugBelief(const char* when) const;
  // What travel may use: the rooms' maps and all the room runs saw (beyond their exits too).
  network::RoomMap knownForTravel() const;
  // Drives to a house cell over the known rooms with the pilot (pose corrections); false when not there.
  bool travelTo(Cell target, const network::RoomMap& known);
  bool step(Dir d);
  // Drives to the exit's inside cell and through it; false when blocked on the way.
  bool passExit(Cell inside, Dir outward, int depth, const network::RoomMap& known);
  // Reads the four sides and moves belief_.cell to the whole-cell shift that explains them best
  // (StandingScan); `blocked`: the direction a move just failed in (nullptr: none). True when the
  // belief moved.
  bool relocalise(const network::RoomMap& known, const Dir* blocked);
  PilotConfig pilotConfig() const;  // for the next pilot: starts with the heading uncertainty handed over
  // The start room's frame moved by the whole cells under which its start readings fit its map again
  // (StartAnchor); the given frame when they fit already or no shift is clear. Sets startShift_.
  network::RoomTransform anchoredStart(const RoomRun& run, const network::RoomTransform& toHouse);

  HouseMapper(sim::RobotPlacement placed, const HouseConfig& config);

  sim::World world_;  // the truth on the robot's grid
  HouseConfig config_;
  ExplorerConfig explorerConfig_;
  mapping::FrameTransform frame_;
  sim::SimRobot robot_;
  std::vector<network::RoomNode> seen_;  // each room run's uncut map and frame
  network::HouseNetwork network_;
  HouseCounters counters_;
  Pose belief_;                  // in the house frame
  int64_t headingVariance_ = 0;  // mrad^2: how well the robot's heading is known between pilots
  std::vector<Pending> pending_;
  std::vector<Cell> openingsTried_;  // inside cells (house frame) of the openings taken as exits
  int exitsFound_ = 0;
  int exitsUnreached_ = 0;
  int relocalisations_ = 0;
  Cell startShift_{0, 0};
};

}  // namespace nxtmap::house
