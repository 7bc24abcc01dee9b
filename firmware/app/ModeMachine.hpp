#pragma once
#include <cstdint>

#include "common/explore/ExplorerStack.hpp"
#include "common/house/HouseBrick.hpp"
#include "common/protocol/BrickLink.hpp"
#include "common/protocol/Command.hpp"
#include "firmware/app/ActionRunner.hpp"
#include "firmware/app/BrickConfig.hpp"
#include "firmware/app/PathFollower.hpp"
#include "firmware/app/PcOutputs.hpp"
#include "firmware/app/WheelStore.hpp"
#include "firmware/drivers/AvrFrame.hpp"
#include "firmware/drivers/MotorSafety.hpp"
#include "firmware/drivers/TachoDecoder.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap::fw {

// The RAM-run image (NXTMAP_RAM_RUN) has no room for the house commands: they are refused there
// like an unknown command (nothing happens), and no HouseBrick code is linked.
#if defined(NXTMAP_RAM_RUN)
inline constexpr bool kHouseCommands = false;
#else
inline constexpr bool kHouseCommands = true;
#endif

// What the brick is doing (protocol::BrickMode) and the commands that change it, from the PC
// (protocol::Command) and from the buttons (Enter: explore with the published method, Right: explore
// with the frontier explorer, Exit: stop, Left: new room). Exploring feeds the ActionRunner the
// ExplorerStack's actions; following a path feeds it the PathFollower's. Mapping a house (a confined
// Explore, GoTo, EnterRoom, Scan from the PC) feeds it the HouseBrick's: while that is active, the mode,
// pose, room and report are the house's; any other command or button, and a fault, aborts it and
// leaves the robot resting where the house believed it. Owns the follower and the robot's resting
// pose; the stack, house, runner, link, safety, tachometers and wheel store are BrickApp's (`house` may be
// nullptr: no house commands; `wheels` nullptr: what is learnt of the wheels lasts until switched off).
// What the runs learnt of the wheels is loaded from `wheels` at construction and saved there when an
// explorer run ends or is stopped.
class ModeMachine {
 public:
  using Mode = protocol::BrickMode;

  NXTMAP_RUN_ONCE ModeMachine(ExplorerStack& stack, HouseBrick* house, ActionRunner& runner, protocol::BrickLink& link,
                              MotorSafety& safety, TachoDecoder& tacho, AvrCommand& motors, const BrickConfig& config,
                              WheelStore* wheels = nullptr)
      : stack_(stack),
        house_(house),
        runner_(runner),
        link_(link),
        safety_(safety),
        tacho_(tacho),
        motors_(motors),
        config_(config),
        store_(wheels) {
    if (store_ != nullptr) (void)store_->load(learnt_);
  }
  ModeMachine(const ModeMachine&) = delete;
  ModeMachine& operator=(const ModeMachine&) = delete;

  // One command from the PC.
  void carryOut(const protocol::Command& c, uint32_t nowMs);
  // The buttons as the AVR reads them now (Button::None when none); a press counts once it has
  // held for kButtonStableMs and differs from the last one that counted.
  void readButton(Button b, uint32_t nowMs);
  // Carries the running action on: when it ends, the motors rest and the explorer or the path
  // gives the next one.
  void drive(uint32_t nowMs);
  // The runner's wheel power into the AVR command (braked when 0); nothing while safety has tripped
  // (the tick holds the motors at 0 with the brake on).
  void driveMotors();
  // The motors must stop (a tripped MotorSafety): the run or path is cut short, mode Fault.
  void halt();

  // LEGO's motor commands from a PC (LegoPort), obeyed only while the robot rests and no fault is
  // latched (else kLegoRequestFailed); the motors then run through driveMotors() and MotorSafety
  // as the robot's own do. `port` 0..2.
  uint8_t setOutput(const protocol::LegoOutputCommand& c);
  uint8_t resetPosition(uint8_t port, bool relative);
  protocol::LegoOutputState output(uint8_t port) const;
  // A motor is powered: the robot moves or a PC drives an output.
  bool motorsDriven() const { return moving() || pc_.driven(); }

  Mode mode() const { return houseActive() ? house_->mode() : mode_; }
  bool moving() const { return mode() == Mode::Exploring || mode() == Mode::Following; }
  // A house command ran since the last other command: mode, pose, room and report are the house's.
  bool houseActive() const { return kHouseCommands && house_ != nullptr && house_->active(); }
  // True while the runner drives either wheel (whatever the mode).
  bool wheelsDriven() const { return runner_.power(0) != 0 || runner_.power(1) != 0; }
  // Where the robot stands: on the path it follows, in the explorer's run, or where it was left.
  Pose pose() const;
  uint16_t roomId() const { return roomId_; }
  const RoomGrid& grid() const { return stack_.map().grid(); }
  // The run's counters, while a run exists (started and not dropped).
  bool hasRun() const { return stack_.running(); }
  Counters counters() const { return stack_.counters(); }
  // Changes whenever the map may have changed (compare with the value last drawn).
  uint32_t mapVersion() const { return mapVersion_; }
  // Counts tasks that ended by themselves (wraps): an explorer run done, a path's goal reached, a
  // house command over. Stops, new rooms and faults do not count (EventBeeper).
  uint8_t finishes() const { return finishes_; }
  protocol::BrickReport report(uint16_t batteryMillivolts) const;

  static constexpr uint32_t kButtonStableMs = 50;
  static constexpr uint8_t kAllBrakes = 0x07;  // outputs A, B, C

 private:
  void startExploring(Strategy s, uint32_t nowMs);
  void followPath(const protocol::PathMsg& path, uint32_t nowMs);
  void takeMapChunk(const protocol::MapChunkMsg& chunk);
  // Stops and stands the robot at `p` (no run holds the pose until the next Explore).
  void restAt(const Pose& p);
  void stop();
  void newRoom();
  void stepExplorer(const DriveEvent& e, uint32_t nowMs);
  // A confined Explore, GoTo, EnterRoom or Scan: started by the HouseBrick from where the robot stands.
  void houseCommand(const protocol::Command& c, uint32_t nowMs);
  // After each house step: the map restart goes to the link, the room id follows, the next action runs.
  void afterHouseStep(const DriveAction& next, uint32_t nowMs);
  // Aborts and deactivates the house (if active): the robot rests where the house believed it.
  void leaveHouse();
  ActionRunner::Wheels wheels() const;
  // The pilot's settings for a new run: what the runs before learnt of the wheels, and (not in the RAM-run
  // image) the start's sweep square to the walls when the map is empty (BrickConfig::squareSweepMrad).
  PilotConfig pilotConfig();
  // What is known of the wheels: the last run's pilot's (an explorer's, a calibration's or the house's),
  // else what the last house command or the store left in learnt_.
  const WheelCalibration& knownWheels();
  // What the explorer run's pilot learnt of the wheels: the next run's start, and into the store (if any).
  void keepWheels();
  // `w` is what is known of the wheels from now on (learnt_), and into the store (if any).
  void keep(const WheelCalibration& w);
  // The PC's Calibrate: a run whose pilot sweeps, turns BrickConfig::calibrationTurns whole turns and sweeps
  // again (TurnCalibration), and ends where its explorer would begin (endCalibration): the wheels kept, the
  // robot resting where it stood, square to the walls. Reported as Exploring meanwhile.
  void calibrate(uint32_t nowMs);
  void endCalibration();
  void mapChanged() { ++mapVersion_; }

  ExplorerStack& stack_;
  HouseBrick* house_;  // nullptr: no house commands (the RAM-run image)
  ActionRunner& runner_;
  protocol::BrickLink& link_;
  MotorSafety& safety_;
  TachoDecoder& tacho_;
  AvrCommand& motors_;  // the AVR link's next command (its motor part)
  const BrickConfig& config_;
  WheelStore* store_;  // nullptr: none
  PathFollower follower_{};
  PcOutputs pc_{};         // outputs as a PC drives them while the robot rests
  DriveAction pending_{};  // the action being carried out
  Pose restPose_{};        // where the robot stands when neither the explorer nor a path moved it last
  WheelCalibration learnt_{};  // what the last run's pilot learnt of the wheels (an uncalibrated robot's first)
  bool poseFromPath_ = false;
  bool calibrating_ = false;  // the run is the PC's Calibrate (ends before its explorer moves)
  Mode mode_ = Mode::Idle;
  uint16_t roomId_ = 0;
  uint32_t mapVersion_ = 1;
  uint8_t finishes_ = 0;
  Button lastButton_ = Button::None;
  Button candidate_ = Button::None;
  uint32_t candidateSince_ = 0;
};

}  // namespace nxtmap::fw
