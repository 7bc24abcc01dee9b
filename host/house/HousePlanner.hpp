// HousePlanner: the PC's part of mapping a house (method section 5), as reports in and orders out.
// The brick (common/house/RoomSession) maps the room it stands in and reports the map and its exits;
// the planner keeps the network of rooms, records each room (cut to its doorways, registered to the
// rooms already mapped, split when too large, joined by gateways), picks the nearest unexplored exit,
// orders the travel there over the known house and the crossing, and, when the robot seems lost by
// a cell (blocked on the way, or no exit reachable from where it believes it stands), orders a
// standing scan and moves its belief to the whole-cell shift that explains it. An exit still not passed
// is tried once more when the others are done, from wherever the robot is then. When no exit is left,
// openings onto unknown space the exits missed are explored the same way; then the house is done.
// The same planner serves `sim-house` (over the simulated drive) and the console (over the link).
#pragma once

#include <vector>

#include "common/house/RoomExit.hpp"
#include "common/house/RoomSession.hpp"
#include "common/interpret/RoomInterpretation.hpp"
#include "common/sensing/RangeGeometry.hpp"
#include "host/network/HouseNetwork.hpp"

namespace nxtmap::house {

struct HousePlannerConfig {
  DoorwayLimits doorways{4, 15, 3, 2};  // the brick's (for reading a room's map on the PC)
  RoomLimits roomLimits{3, 80};         // an open area over 8 m (at 10 cm cells) is several rooms
  int maxRooms = 40;                    // safety stop
  int registerCells = 2;                // a new room's frame may shift this far to fit the rooms mapped (0: off)
  int maxOpenings = 6;                  // openings onto unknown space the exits missed, explored at the end (0: none)
  // A robot blocked on its way to an exit, or with no exit reachable from where it believes it stands,
  // scans the four sides and moves its belief by the whole cells (up to this many each way) that fit
  // the map best, then tries once more (0: off).
  int relocaliseCells = 2;
  int poseRangeCm = 0;  // the pilot's pose range (landmarks out to max(geometry.maxCm, this))
  // The brick's grid (cells per side): a travel's map is cut to it, and a way longer than it fits
  // is driven in legs.
  int gridCells = 64;
};

// What the PC asks the brick to do next.
struct HouseOrder {
  enum class Kind { ExploreFirstRoom, Travel, Cross, Scan, Finished };
  Kind kind = Kind::Finished;
  // Travel: the known house in a frame with the robot at its origin facing +y: the brick's map is
  // replaced by it (cells beyond the grid's capacity left out) and the robot drives to `target`.
  network::RoomMap map;
  Cell target{};
  // Cross: the robot stands at `at` (the brick's current frame) and crosses `exit` (same frame).
  Pose at{};
  RoomExit exit{};
};

// What the brick did.
struct HouseReport {
  enum class Kind { RoomMapped, Arrived, NotArrived, CrossBlocked, Scanned };
  Kind kind = Kind::RoomMapped;
  Pose pose{};  // the believed pose in the brick's current frame
  // RoomMapped: everything the room's run saw (doors open again), its exits, the cells the robot stood
  // in (stood), and (after a Cross) the new room's origin and +y in the frame the robot crossed from.
  network::RoomMap map;
  std::vector<RoomExit> exits;
  Pose crossedAt{};
  RangeReading scan[kSensorCount] = {};  // Scanned: Front, Right, Back, Left
  std::vector<Cell> stood;  // RoomMapped: cells the robot believed it stood in while mapping (room frame, in order)
};

class HousePlanner {
 public:
  HousePlanner(const HousePlannerConfig& config, const RangeGeometry& geometry);

  HouseOrder start();
  HouseOrder on(const HouseReport& report);

  const network::HouseNetwork& network() const { return network_; }
  network::HouseNetwork& network() { return network_; }
  bool finished() const { return phase_ == Phase::Done; }
  int exitsFound() const { return exitsFound_; }
  int exitsUnreached() const { return exitsUnreached_; }
  int relocalisations() const { return relocalisations_; }
  int openingsTried() const { return static_cast<int>(openingsTried_.size()); }
  int exitsLeft() const { return static_cast<int>(pending_.size()); }
  const Pose& belief() const { return belief_; }  // house frame
  // The brick's current frame (the room being mapped, or the travel's) -> house.
  const network::RoomTransform& brickToHouse() const { return brickToHouse_; }

 private:
  enum class Phase { FirstRoom, Travel, Cross, ScanNoExit, ScanBlocked, Done };
  struct Pending {
    int room;
    RoomExit exit;       // in the room's frame
    bool retry = false;  // not passed once already: not tried again
  };

  // The flow (HousePlanner.cpp).
  HouseOrder nextExit();    // the loop over pending exits: the next order
  HouseOrder endOfExits();  // no exit left: an opening, or done
  HouseOrder passExit();    // to current_'s inside cell (in legs the grid holds) and through it
  // House frame: the farthest cell along the way to `inside` one leg reaches, and the box of the
  // brick's grid (gridCells a side) that holds the leg.
  Cell legEnd(Cell inside, Bounds& box) const;
  HouseOrder crossOrder();
  HouseOrder failedPass();
  void notPassed();  // current_ was not passed: kept for one more try (failed_), or counted unreached
  HouseOrder scanned(const HouseReport& r);
  Cell standingShift(const HouseReport& r, const Dir* blocked) const;
  network::RoomMap knownForTravel() const;

  // Recording a room (HousePlannerRooms.cpp).
  void recordRoom(const HouseReport& r, int fromRoom, const RoomExit* via, const std::vector<Cell>& entranceHouse);
  bool leadsToMappedRoom(const Pending& p);
  // Adds a gateway with the pairs of cells neither room's map holds as a wall (a doorway seen from one room
  // may fall a cell into the other's wall); none left: no gateway. The house stays valid to save.
  void addPassableGateway(network::Gateway g);
  bool queueOpening();

  HousePlannerConfig config_;
  RangeGeometry geometry_;
  Phase phase_ = Phase::FirstRoom;
  network::HouseNetwork network_;
  std::vector<network::RoomNode> seen_;  // each room run's uncut map and frame
  std::vector<Pending> pending_;
  std::vector<Pending> failed_;          // exits not passed once, tried again when pending_ is done
  std::vector<Cell> openingsTried_;      // inside cells (house frame) of the openings taken as exits
  Pose belief_{};                        // house frame
  network::RoomTransform brickToHouse_;  // the brick's current frame -> house
  Pending current_{};                    // the exit being passed
  int attempt_ = 0;                      // of passing current_ (a second after a relocalisation)
  bool relocalisedHere_ = false;         // since the robot last moved
  Dir facing_ = Dir::North;              // house frame: where the robot was blocked
  network::RoomMap known_;               // what travel may use, for the current exit
  int exitsFound_ = 0;
  int exitsUnreached_ = 0;
  int relocalisations_ = 0;
};

// The exit's cells, along the doorway then across it.
std::vector<Cell> cellsOf(const Doorway& door);
// An exit in another frame (via `t`): the same cells, inside cell and direction.
RoomExit transformExit(const RoomExit& e, const network::RoomTransform& t);

}  // namespace nxtmap::house
