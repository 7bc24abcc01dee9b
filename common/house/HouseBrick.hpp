// HouseBrick: the house commands as the brick carries them out, shared by the firmware's mode
// machine and the stand-in brick: a confined Explore (map the room the robot stands in), GoTo (drive
// to a cell of the map held), EnterRoom (cross a doorway into the next room and map it) and Scan
// (read the four sensors standing), each run by the RoomSession, and what the brick reports of them
// (room ids, the new room's frame, the goal's progress, the room's exits, the last scan). Events in, actions out; the caller carries the actions out.
#pragma once
#include <cstdint>

#include "common/house/RoomSession.hpp"
#include "common/protocol/BrickLink.hpp"

namespace nxtmap {

class HouseBrick {
 public:
  HouseBrick(ExplorerStack& stack, RoomConfinement& confinement, const PilotConfig& pilot);

  // Each starts its command from `here` (the believed pose on the map held) and returns the first
  // action (Done: over at once). A confined explore starts a new room (the one after `roomId`, the
  // brick's room so far): the map is cleared.
  DriveAction explore(const protocol::ExploreMsg& how, const Pose& here, uint16_t roomId);
  DriveAction goTo(const protocol::GoToMsg& goal, const Pose& here);
  DriveAction enterRoom(const protocol::EnterRoomMsg& m, const Pose& here);
  DriveAction scan(const protocol::ScanMsg& m, const Pose& here);
  DriveAction step(const DriveEvent& e);
  // Stops the command (Stop, a fault, another command): the robot stands where it is believed.
  void abort();
  // What the house's runs learnt of the wheels (the next run's start); useWheels, before the first command
  // of a house: what the brick knows of them (stored, calibrated, learnt by its other runs).
  const WheelCalibration& wheels() const { return session_.wheels(); }
  void useWheels(const WheelCalibration& w) { session_.useWheels(w); }

  bool running() const { return session_.busy(); }
  // A house command ran since the last other command: its state is what the brick reports.
  bool active() const { return active_; }
  void deactivate() { active_ = false; }
  Pose pose() const { return session_.pose(); }
  // The map was cleared for a new room since the last call (the link must send it afresh).
  bool takeMapRestart();
  // The mode the brick reports while a house command is active.
  protocol::BrickMode mode() const;
  // Room ids, the new room's frame, the goal's progress, the room's exits and the readings, into `r`.
  void fill(protocol::BrickReport& r) const;
  uint16_t roomId() const { return roomId_; }
  const RoomSession& session() const { return session_; }

 private:
  void noteNewRoom();
  void over();            // the command is over: the goal's end, or the room's exits
  void resetExits();      // a new room: no exits yet, running
  void updateExits();     // the room is mapped: its exits and how its run ended
  void updateReadings();  // after every start and step: the scan, when over

  ExplorerStack& stack_;
  RoomConfinement& confinement_;
  RoomSession session_;
  bool active_ = false;
  bool mapRestart_ = false;
  uint16_t roomId_ = 0, fromRoom_ = 0, pendingRoom_ = 0;
  Pose origin_{};  // the current room's origin and +y in the frame of the room before it
  uint16_t roomsSeen_ = 0;
  protocol::PathProgressMsg goal_{};
  protocol::RoomExitsMsg exits_{};
  uint16_t scanId_ = 0;  // the Scan command running (0: none)
  protocol::ReadingsMsg readings_{};
};

}  // namespace nxtmap
