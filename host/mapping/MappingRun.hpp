#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "common/explore/ExplorerStack.hpp"
#include "common/sensing/RangeFilter.hpp"
#include "host/mapping/ExplorerBuffer.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/mapping/Strategy.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/Site.hpp"
#include "host/sim/TruthRaster.hpp"
#include "host/sim/World.hpp"

#include <optional>

namespace nxtmap::mapping {

struct RunConfig {
  int startCol = 0, startRow = 0;           // start cell in the site's raster (when startPose is empty);
                                            // after construction (MappingRun::config): in the truth raster
  sim::Heading heading = sim::Heading::N;   // initial heading in the world (when startPose is empty)
  std::optional<sim::StartPose> startPose;  // a start in the plane instead of a raster cell
  double startJitterDeg = 0.0;              // > 0: set down off the cell centre and up to this many degrees off square
  bool squareAtStart = false;               // the pilot turns square to the walls before mapping (StartSquaring)
  int calibrateTurns = 0;                   // > 0: and first measures its turns' error (TurnCalibration; implies
                                            // squareAtStart), correcting every turn after it
  // With squareAtStart and no calibrateTurns: a robot that knows its turns no better than an uncalibrated one
  // (its wheels as stored, WheelCalibration::turnsUnknown) calibrates first all the same, as the brick does
  // (PilotConfig::calibrateUnknownTurns). false: never unasked.
  bool calibrateUnknownTurns = true;
  // The robot: its cell, body and sensor mounts, and the range it trusts (its minRangeM/rangeM replace the
  // two below). Empty: a point robot of the raster's own cells with the ranges below (the published set-up).
  std::optional<sim::RobotDescription> robot;
  double rangeM = 1.0;           // trusted maximum range (published: 1 m)
  double minRangeM = 0.05;       // trusted minimum range (published: 5 cm)
  double sensorReachCm = 255.0;  // the sonar's own reach (NXT: 255 = no echo)
  sim::NoiseProfile noise;       // see sim::noiseProfileByName
  uint64_t seed = 1;
  Strategy strategy = Strategy::Propagation;
  double beamHalfAngleDeg = -1.0;  // the robot's sonar beam, known to it (< 0: the noise profile's cone)
  int blindCm = -1;                // the sensor's blind zone, known to it (< 0: the noise profile's, sonarBlindCm)
  bool poseCorrection = true;      // the pilot keeps the robot on the grid (off: dead reckoning)
  // What the robot holds of its wheels from earlier runs (what a pilot learnt: Pilot::wheels), as the brick keeps
  // it; empty: nothing stored, the wheels' error sizes only (storedCalibration).
  std::optional<WheelCalibration> storedWheels;
  uint16_t searchSliceStates = 8;  // travel-search states per explorer step (brick CPU budget)
  // The firmware pings one sensor at a time (single shot, SonarSequencer); true fires every read as if the
  // other sensors pinged at the same moment (continuous mode), so their cross-talk shows.
  bool sensorsTogether = false;
  // The room grid the explorer maps into: the brick's 64 x 64 cells unless chosen otherwise. A room wider
  // than the grid is mapped up to the grid's edge and the run ends GridFull, as on the brick.
  GridCapacity grid = GridCapacity::brick();
};

// One mapping run: the common core's explorer and pilot driven by the simulated robot, exactly as
// the firmware drives them with the real drivers (read -> filter samples -> event, rotate, drive).
class MappingRun {
 public:
  // A run in `site` (kept alive by the run through its scene; its raster is copied).
  MappingRun(const sim::Site& site, const RunConfig& config);
  // A run in a raster world: the world traced into a scene (the published set-up).
  MappingRun(const sim::World& world, const RunConfig& config);
  ~MappingRun();

  // Carries out one action and feeds the result back. False once the run is over.
  bool step();
  // Runs until the explorer is done; returns the number of actions carried out.
  uint64_t runToEnd();

  const Explorer& explorer() const { return *stack_.explorer(); }
  const PropagationExplorer* propagation() const { return stack_.propagation(); }
  Counters counters() const { return stack_.counters(); }
  bool finished() const { return stack_.finished(); }
  const DriveAction& lastAction() const { return last_; }
  // What the robot answered to the action step() carried out last (a reading, a turn, a drive).
  const DriveEvent& lastEvent() const { return lastEvent_; }
  const Pilot& pilot() const { return *stack_.pilot(); }  // only when hasPilot()
  bool hasPilot() const { return stack_.pilot() != nullptr; }
  const sim::SimRobot& robot() const { return robot_; }
  // The truth on the robot's grid (the safe rule: a cell holding any part of an obstacle is blocked).
  const sim::World& world() const { return truth_; }
  const sim::RobotDescription& robotDescription() const { return robot_.description(); }
  const RunConfig& config() const { return config_; }
  const FrameTransform& frame() const { return frame_; }
  const ExplorerConfig& explorerConfig() const { return stack_.config(); }
  const GridCapacity& grid() const { return buffer_.capacity(); }

  // The grid's turn as the robot was set down, compass degrees (the start jitter's turn).
  double setDownFrameDeg() const { return setDownFrameDeg_; }
  // How far the robot was carried from where it was asked to be set down, to have room to turn (cm; 0 not
  // moved, < 0 no spot nearby had room): sim::RobotPlacement::startMovedCm.
  double startMovedCm() const { return startMovedCm_; }
  // Once the sweep found the walls (RunConfig::squareAtStart): how far, degrees (>= 0), the robot was left
  // off their nearest axis, the error its map is scored with.
  double squaredOffDeg() const { return squaredOffDeg_; }
  // The same with its sign, + the robot clockwise of the walls' axis (-45..45); empty when the sweep found no wall
  // or there was no sweep.
  std::optional<double> squaredTurnedDeg() const { return squaredTurnedDeg_; }
  // The sweeps saw no straight wall and the truth was laid again once the walls it mapped had squared the robot
  // (layTruthLate).
  bool squaredLate() const { return squaredLate_; }

  // Whether the room met the grid's edge: the run ended GridFull (a reading or a move beyond the grid), or
  // it left open space unmapped where the grid ends (the frontier explorer stops there and ends Complete).
  bool metGridEdge() const;

  // The explorer's belief about a world cell (Unknown outside what it mapped).
  CellState belief(int col, int row) const;
  // The believed robot cell in world coordinates.
  void believedCell(int& col, int& row) const;
  sim::Heading believedHeading() const;

 private:
  struct Setup;  // the placement worked out before the members are built
  MappingRun(Setup setup, const RunConfig& config);
  DriveEvent carryOut(const DriveAction& a);

  // After the pilot turned square to the walls (RunConfig::squareAtStart): the truth laid again on the grid
  // the robot now maps in, turned to the scene's walls nearest its heading (sim::sceneAxesDeg), centred where
  // it stands; what is left of its heading error counts against it.
  void layTruthSquare();
  // A robot whose sweeps saw no straight wall squares against the walls while mapping: once its heading is known
  // as well as a squared start's (twice PilotConfig::squaredHeadingMrad, 1 sigma), the truth is laid again where
  // its belief holds (believedGrid); the cells it mapped before are scored on that grid too.
  void layTruthLate();
  // The truth drawn on grid p, the explorer's origin at cell originCol, originRow and its north `heading` there.
  void layTruthOn(const sim::Placement& p, int originCol, int originRow, sim::Heading heading);

  RunConfig config_;
  bool squared_ = false;  // layTruthSquare has run
  bool squareLate_ = false;   // the sweeps saw no wall: layTruthLate is due once the heading is known
  bool squaredLate_ = false;  // layTruthLate has run
  double startMovedCm_ = 0;
  double setDownFrameDeg_ = 0;  // the grid's turn as the robot was set down (sim::GridFrame::headingDeg)
  sim::Vec2 setDownCm_;         // where the robot's centre was set down (plane, cm)
  double squaredOffDeg_ = 0;    // after the sweep: degrees from the robot's heading to the walls' nearest axis
  std::optional<double> squaredTurnedDeg_;  // the same, signed; found walls only
  sim::World truth_;
  FrameTransform frame_;
  sim::SimRobot robot_;
  ExplorerBuffer buffer_;  // the memory of stack_, of config_.grid's capacity
  ExplorerStack stack_;    // one run of config_.strategy, started in the constructor
  DriveAction last_;
  DriveEvent lastEvent_;
};

}  // namespace nxtmap::mapping
