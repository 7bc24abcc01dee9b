// RoomSession: the brick's part of mapping a house, as events in (DriveEvent) and actions out
// (DriveAction), over the one ExplorerStack. Three commands, each ending in an outcome:
//  - exploreRoom: map the room the robot stands in, kept in it by RoomConfinement (the entrance it
//    came through held shut); ends RoomMapped with the room's exits;
//  - goTo: drive to a cell over the map held (the way to an exit), with the pilot's pose
//    corrections; ends Arrived or NotArrived;
//  - cross: from an exit's inside cell, turn outward and cross the doorway cell by cell
//    (dead-reckoned), then start the next room there at once (its frame: origin where the robot
//    stands, +y outward) and map it; ends RoomMapped, or CrossBlocked if a cell could not be entered;
//  - scan: one filtered reading of each sensor where the robot stands (for the PC to tell where it
//    is when it seems lost); ends Scanned.
// After a run the robot is levelled on its axis so the next pilot starts exactly on it, and the
// heading's remaining variance is handed to that pilot. Which exit to take, and what the rooms mean
// together, is decided by the PC (host/house/HousePlanner).
#pragma once
#include <cstdint>

#include "common/explore/ExplorerStack.hpp"
#include "common/house/RoomConfinement.hpp"
#include "common/house/RoomExit.hpp"

namespace nxtmap {

class RoomSession {
 public:
  enum class Phase : uint8_t { Idle, Exploring, Travelling, Crossing, Levelling, Scanning };
  enum class Outcome : uint8_t { None, RoomMapped, Arrived, NotArrived, CrossBlocked, Scanned };
  // `pilot`: how every run's pilot keeps the robot on the grid (its start heading variance is the
  // session's own). The stack and the confinement are the caller's and outlive the session.
  RoomSession(ExplorerStack& stack, RoomConfinement& confinement, const PilotConfig& pilot);

  // Maps the room the robot stands in from `at`, on the map as it is (a new room: cleared, Pose{});
  // `entrance` (room frame) is held shut (nullptr: none, the first room).
  DriveAction exploreRoom(Strategy strategy, const Pose& at, const Doorway* entrance);
  // Drives to `target` over the map held, from `at`. Done at once (Arrived) when already there.
  DriveAction goTo(Cell target, const Pose& at);
  // From pose(), crosses `exit` (room frame) and maps the room beyond with `strategy`.
  DriveAction cross(const RoomExit& exit, Strategy strategy);
  // Reads the four sensors where the robot stands (scanReading()).
  DriveAction scan();
  // Feeds the answer to the last action; returns the next (Done: the command is over, see outcome()).
  DriveAction step(const DriveEvent& e);

  Phase phase() const { return phase_; }
  bool busy() const { return phase_ != Phase::Idle; }
  Outcome outcome() const { return outcome_; }
  // The believed pose in the current room's frame.
  Pose pose() const;
  // After a cross: the new room's origin and +y in the frame of the room the robot came from.
  const Pose& crossedAt() const { return crossedAt_; }
  uint16_t roomsStarted() const { return roomsStarted_; }
  int64_t headingVarianceMrad2() const { return headingVariance_; }
  void setHeadingVarianceMrad2(int64_t v) { headingVariance_ = v; }
  // Stops the command where the robot is believed to be (no outcome).
  void abort();
  // Moves the belief to `p` (e.g. a relocalisation by the PC); only while idle.
  void setPose(const Pose& p);
  // The wheels the next run starts from: what the last run learnt of them (Pilot::wheels at its end), or
  // what useWheels gave. useWheels: only while idle.
  const WheelCalibration& wheels() const { return pilot_.wheels; }
  void useWheels(const WheelCalibration& w) { pilot_.wheels = w; }
  // After scan(): the reading of sensor s.
  const RangeReading& scanReading(Sensor s) const { return scan_[static_cast<int>(s)]; }
  // The last room's and the travels' counters, summed since construction.
  const Counters& exploreCounters() const { return explore_; }
  const Counters& travelCounters() const { return travel_; }
  uint32_t travelsNotArrived() const { return travelsNotArrived_; }

 private:
  PilotConfig pilotConfig() const;
  DriveAction stepExploring(const DriveEvent& e);
  DriveAction stepTravelling(const DriveEvent& e);
  DriveAction finishExploring();   // the room's run is over
  DriveAction finishTravelling();  // the travel is over
  DriveAction stepCrossing(const DriveEvent& e);
  DriveAction stepScanning(const DriveEvent& e);
  DriveAction crossNext();
  // The run is over: level the robot (an action) or end the command at once (Done).
  DriveAction endRun(Outcome outcome);
  DriveAction finishCommand();

  ExplorerStack& stack_;
  RoomConfinement& confinement_;
  PilotConfig pilot_;  // every run starts from it; its wheels follow what each run learnt (Pilot::wheels)
  Phase phase_ = Phase::Idle;
  Outcome outcome_ = Outcome::None;
  Outcome pendingOutcome_ = Outcome::None;  // while levelling
  Pose idlePose_{};
  DriveAction last_{};
  int64_t headingVariance_ = 0;  // mrad^2, between runs
  // Crossing: where the robot is (old frame), the exit, cells left to cross, the next strategy.
  RoomExit exit_{};
  Pose crossPose_{};
  Pose crossedAt_{};
  int16_t crossLeft_ = 0;
  Strategy nextStrategy_ = Strategy::Frontier;
  uint16_t roomsStarted_ = 0;
  RangeReading scan_[kSensorCount] = {};
  uint8_t scanNext_ = 0;
  Counters explore_{}, travel_{};
  uint32_t travelsNotArrived_ = 0;
};

}  // namespace nxtmap
