// HouseMapper: maps a house in the simulator, room by room (method section 5), by running the one
// house logic over the simulated robot: the PC's HousePlanner decides (which exit next, the rooms'
// network, relocalisation) and the brick's RoomSession carries its orders out (map the room, kept in
// it; travel; cross a doorway; scan) on the common explorer stack, exactly as on the brick. This
// runner only carries actions out on the simulated robot and hands reports back: no decision is
// made here. One simulated robot keeps its true pose throughout.
#pragma once

#include <cstdint>
#include <vector>

#include "common/explore/Counters.hpp"
#include "common/interpret/Doorway.hpp"
#include "common/interpret/RoomInterpretation.hpp"
#include "common/explore/ExplorerStack.hpp"
#include "common/house/RoomConfinement.hpp"
#include "common/house/RoomSession.hpp"
#include "host/house/HousePlanner.hpp"
#include "host/house/HouseTrace.hpp"
#include "host/mapping/ExplorerBuffer.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/mapping/Strategy.hpp"
#include "host/network/HouseNetwork.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/TruthRaster.hpp"
#include "host/sim/SimRobot.hpp"
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
  bool squareAtStart = false;  // the first room's run sweeps square to the walls first (PilotConfig::squareSweepMrad)
  int calibrateTurns = 0;      // > 0, with squareAtStart: and measures its turns' error there first (calibrateTurns)
  // With squareAtStart and no calibrateTurns: a robot that knows its turns no better than an uncalibrated one
  // measures them unasked, as the brick does (PilotConfig::calibrateUnknownTurns). false: never unasked.
  bool calibrateUnknownTurns = true;
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
  // The explorer's grid: the brick's 64 x 64 cells unless chosen otherwise.
  mapping::GridCapacity grid = mapping::GridCapacity::brick();
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

  const network::HouseNetwork& network() const { return planner_.network(); }
  network::HouseNetwork& network() { return planner_.network(); }
  HouseCounters counters() const;
  int exitsFound() const { return planner_.exitsFound(); }
  int exitsUnreached() const { return planner_.exitsUnreached(); }    // exits the robot could not get through
  int relocalisations() const { return planner_.relocalisations(); }  // beliefs moved by a standing scan
  int openingsTried() const { return planner_.openingsTried(); }      // see HouseConfig::maxOpenings
  const sim::SimRobot& robot() const { return robot_; }
  // What the house's runs learnt of the wheels (the pilots' drift and turn error, RoomSession::wheels).
  const WheelCalibration& wheels() const { return session_.wheels(); }
  // The first room's turn calibration (HouseConfig::calibrateTurns, or one unasked): turns 0 when none ran.
  struct StartCalibration {
    int turns = 0;  // whole turns between its two sweeps
    bool found = false;
    int32_t errorPpm = 0;  // the turns' error it measured (found only)
    bool turnedBack = false;  // not found: the second sweep lost the walls and the whole turns were turned back
  };
  const StartCalibration& startCalibration() const { return startCalibration_; }
  const sim::World& world() const { return world_; }
  const HouseConfig& config() const { return config_; }
  const ExplorerConfig& explorerConfig() const { return explorerConfig_; }
  // House frame (room 0: origin at the start, +y the initial heading) <-> world cells.
  const mapping::FrameTransform& houseFrame() const { return frame_; }
  // Every action from now on is written to `trace` (nullptr: none; not owned, must outlive the run).
  void setTrace(HouseTrace* trace) { trace_ = trace; }

 private:
  HouseMapper(sim::RobotPlacement placed, const HouseConfig& config);
  // Carries an order out with the session on the simulated robot; the brick's report of it.
  HouseReport carryOut(const HouseOrder& o);
  void drive(DriveAction a);               // until the session's command is over
  void load(const network::RoomMap& map);  // the brick's map replaced (as an upload from the PC)
  HouseReport report(HouseReport::Kind kind) const;
  void logBelief(const char* when) const;
  void noteWhereItStands();  // the believed cell against the simulated robot's (log debug)
  // For trace_: the action carried out in `phase` of the session and its answer, with the poses as they now stand.
  HouseTraceRow traceRow(RoomSession::Phase phase, const DriveAction& done, const DriveEvent& answer) const;
  // Once the first room's sweep is over: the truth laid on the grid the robot now maps on (SquaredGrid).
  void layTruthSquare();
  // The sweeps saw no straight wall: once the heading is known from the first room's walls, the truth laid again
  // where the robot's belief holds (mapping::believedGrid; as MappingRun).
  void layTruthLate();
  // The truth drawn on grid p, the first room's origin at cell originCol, originRow and its north `heading` there.
  void layTruthOn(const sim::Placement& p, int originCol, int originRow, sim::Heading heading);
  bool squared_ = false;     // layTruthSquare has run (or there is no sweep)
  bool squareLate_ = false;  // layTruthLate is due (the first room's run, heading not yet known)
  StartCalibration startCalibration_{};
  sim::Vec2 setDownCm_;   // where the robot's centre was set down (plane, cm)

  sim::World world_;  // the truth on the robot's grid
  HouseConfig config_;
  ExplorerConfig explorerConfig_;
  mapping::FrameTransform frame_;
  sim::SimRobot robot_;
  mapping::ExplorerBuffer memory_;
  ExplorerStack stack_;
  std::vector<uint8_t> reachBits_;
  RoomConfinement confinement_;
  RoomSession session_;
  HousePlanner planner_;
  HouseTrace* trace_ = nullptr;
  std::vector<Cell> stood_;  // the room run's believed cells so far (HouseReport::stood)
};

}  // namespace nxtmap::house
