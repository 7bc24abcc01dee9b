// SimBrick: a stand-in for the brick, on the PC. It is built like the firmware's BrickApp: one
// room map (the common core's MapLayers) that the explorer maps into, the PC's uploads load into
// and the brick's own protocol code (BrickLink, MapSync) keeps the PC's copy equal to; the
// common core's explorer and pilot drive the simulated robot (host/mapping SimDrive) exactly as
// the firmware drives the real one. Used to test the link end to end and by
// `nxtmap connect sim:WORLD` until the emulated brick runs the real firmware.
//
// As on the brick: an upload (MapChunk) replaces the map and keeps the pose in the same frame;
// SetPose says where the robot stands on the map it holds (e.g. a room just uploaded, in that
// room's frame); Explore resumes a stopped run, or starts a new run on the map as it is from
// where the robot stands (after a path, an upload or SetPose); newRoom() is the Left button.
//
// Stand-in simplifications: paths are followed on the world's truth, one cell per cellMs,
// without sensing (the robot is put on each cell's centre); runs start from the noise preset's stored wheel
// calibration (mapping::storedCalibration) until a Calibrate measured the turns, and do not sweep first.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "common/explore/ExplorerStack.hpp"
#include "common/house/HouseBrick.hpp"
#include "common/protocol/BrickLink.hpp"
#include "host/mapping/ExplorerBuffer.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/mapping/MappingRun.hpp"
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::link {

struct SimBrickConfig {
  mapping::RunConfig run;  // start cell and heading in the world, noise, strategy, grid (the brick's), ...
  uint32_t actionMs = 20;  // one explorer action (read / move / turn) every this many ms
  uint32_t cellMs = 100;   // path following: one cell every this many ms
  uint16_t batteryMillivolts = 7800;
  protocol::BrickLinkConfig link;
};

class SimBrick {
 public:
  // The robot set down in `site` as config.run says (start, robot, jitter, noise); the site's scene is shared.
  SimBrick(const sim::Site& site, const SimBrickConfig& config);
  SimBrick(const sim::World& world, const SimBrickConfig& config);
  ~SimBrick();

  void receive(const uint8_t* data, size_t size);
  // Up to maxBytes of what the brick sends now (whole frames are queued; bytes leave in order).
  std::vector<uint8_t> transmit(uint32_t nowMs, size_t maxBytes);
  // Carries out commands and moves the robot up to nowMs.
  void step(uint32_t nowMs);
  void linkLost();
  // The Left button: a new room starts where the robot stands (empty map, pose (0,0) facing +y).
  void newRoom();

  const RoomGrid& grid() const { return stack_.map().grid(); }
  const sim::World& world() const { return world_; }  // the truth on the robot's grid
  const ExplorerConfig& explorerConfig() const { return stack_.config(); }
  protocol::BrickMode mode() const { return mode_; }
  const protocol::BrickLink& link() const { return link_; }
  // The current run's explorer counters (zero before the first Explore), as the brick reports them.
  Counters counters() const;
  // Whether the current exploring run is over (false before the first Explore).
  bool finished() const;
  // Sequence numbers of every command carried out, in order (the test for "never twice").
  const std::vector<uint16_t>& executed() const { return executed_; }
  // The brick's pose in its map's frame.
  Pose pose() const;
  // What the brick has learnt of its wheels (the run's pilot; before a run, what its store holds).
  WheelCalibration wheels() const;
  const protocol::PathProgressMsg& path() const { return path_; }
  uint32_t mapChunks() const { return mapChunks_; }
  uint16_t roomId() const { return roomId_; }
  // The house commands' state (rooms started, the room's exits, ...).
  const HouseBrick& house() const { return house_; }
  // The robot's true cell in the world, and the world cell of a cell of the brick's map.
  void trueCell(int& col, int& row) const;
  void toWorld(Cell c, int& col, int& row) const { frame_.toWorld(c, col, row); }

 private:
  // A run's (and the house's) pilot: pose correction as configured, the wheels as the store holds them.
  PilotConfig pilotConfig() const;
  void carryOut(const protocol::Command& c);
  void startExploring();
  // Calibrate, as the brick's ModeMachine does: a run whose pilot sweeps, turns and sweeps again where the
  // robot stands (TurnCalibration), ended when its explorer would begin; what it learnt starts later runs.
  void calibrate();
  void endCalibration();
  void takeMapChunk(const protocol::MapChunkMsg& chunk);
  void setPose(const Pose& p);
  void stopMoving();
  void exploreOne();
  void houseOne();  // one action of a house command (HouseBrick)
  void houseCommand(const protocol::Command& c);
  void newRoomFrame(const Pose& origin);  // the map's frame moves to a new room whose origin is `origin`
  void followOne();
  bool worldBlocked(Cell c) const;
  protocol::BrickReport report() const;

  SimBrick(sim::RobotPlacement placed, const SimBrickConfig& config);

  sim::World world_;  // the truth on the robot's grid
  SimBrickConfig config_;
  // What a Calibrate or the last house learnt (none: the noise preset's stored calibration); before house_,
  // whose construction asks pilotConfig().
  std::optional<WheelCalibration> learnt_;
  mapping::FrameTransform frame_;  // the brick map's frame -> world cells (changes with SetPose / new room)
  sim::SimRobot robot_;
  mapping::ExplorerBuffer buffer_;  // the memory of stack_, of config_.run.grid's capacity
  ExplorerStack stack_;             // the room map and the current run (none: a new run starts at restPose_)
  std::vector<uint8_t> reach_;      // the confinement's flood bits
  RoomConfinement confinement_;
  HouseBrick house_;       // the house commands (confined explore, goto, enter room)
  DriveAction pending_{};  // the action the pilot asked for last
  Pose restPose_{};        // where the robot stands when no run holds its pose
  bool calibrating_ = false;  // the run is a Calibrate (ends before its explorer moves)
  std::vector<uint8_t> shadow_;
  protocol::BrickLink link_;
  protocol::BrickMode mode_ = protocol::BrickMode::Idle;
  uint16_t roomId_ = 0;
  uint32_t nextActionMs_ = 0;
  protocol::PathMsg pathMsg_;
  protocol::PathProgressMsg path_;
  std::vector<uint16_t> executed_;
  std::vector<uint8_t> txQueue_;
  uint32_t mapChunks_ = 0;
};

}  // namespace nxtmap::link
