#pragma once
#include <cstdint>

#include "firmware/drivers/AvrFrame.hpp"

namespace nxtmap::fw {

// The motor safety stop. The AVR keeps the motors at the last power it received if the ARM goes
// quiet, so the ARM must stop them itself: the 1 ms tick (which owns the AVR link) calls enforce()
// on every outgoing command. Motors are forced to 0 % with the brake on while a fault is latched
// (check failure, encoder fault, AVR link lost while driving) or when the control loop in the main
// loop has not called feed() for kSilenceMs while a motor is driven (it hung or stalls with the
// wheels turning; a long explorer decision with the motors at rest is not a fault). A latched fault
// stays until clear().
class MotorSafety {
 public:
  enum class Reason : uint8_t { None, Check, Encoder, AvrLink, ControlSilent };
  static constexpr uint32_t kSilenceMs = 50;

  // The control loop is alive (main loop, every pass).
  void feed(uint32_t nowMs) {
    lastFeedMs_ = nowMs;
    fed_ = true;
  }
  // Latches a fault (first reason wins).
  void trip(Reason r) {
    if (reason_ == Reason::None) reason_ = r;
  }
  void clear() { reason_ = Reason::None; }
  Reason reason() const { return reason_; }
  bool tripped() const { return reason_ != Reason::None; }

  // 1 ms tick: latches ControlSilent when the loop went quiet with a motor driven, then zeroes and
  // brakes the motors of `cmd` if anything is latched. Returns true when the motors were forced off.
  bool enforce(AvrCommand& cmd, uint32_t nowMs) {
    const bool driven = cmd.pwm[0] != 0 || cmd.pwm[1] != 0 || cmd.pwm[2] != 0 || cmd.pwm[3] != 0;
    if (fed_ && driven && nowMs - lastFeedMs_ > kSilenceMs) trip(Reason::ControlSilent);
    if (!tripped()) return false;
    for (int m = 0; m < 4; ++m) cmd.pwm[m] = 0;
    cmd.brakeMask = 0x07;
    return true;
  }

 private:
  volatile uint32_t lastFeedMs_ = 0;
  volatile bool fed_ = false;
  volatile Reason reason_ = Reason::None;
};

}  // namespace nxtmap::fw
