#pragma once
#include <cstdint>

#include "common/protocol/Messages.hpp"

namespace nxtmap::fw {

// One short tone: frequency in Hz (0: none), duration in ms.
struct Beep {
  uint16_t hz = 0;
  uint16_t ms = 0;
};

// Short beeps on the brick's own events, chosen from what the ModeMachine shows after each main-loop
// pass: a task that ended by itself (ModeMachine::finishes() moved on) in mode Done is a room's run
// that ended (the explorer's, or the house's room mapped); in mode Idle a goal reached (the path's end,
// or the house's command over). Entering Fault (the motors stopped by the safety) gets a low tone.
// Tones stay within the Speaker's 220..14080 Hz, at least 10 ms. Owned by BrickApp.
class EventBeeper {
 public:
  static constexpr Beep kRunEnded{1760, 150}, kGoalReached{880, 100}, kFault{220, 300};

  // The tone for what changed since the last call (hz 0: none). `finishes` counts tasks that ended
  // by themselves (wraps).
  Beep update(protocol::BrickMode mode, uint8_t finishes) {
    using Mode = protocol::BrickMode;
    const bool finished = finishes != finishes_;
    const bool fault = mode == Mode::Fault && mode_ != Mode::Fault;
    finishes_ = finishes;
    mode_ = mode;
    if (fault) return kFault;
    if (!finished) return Beep{};
    if (mode == Mode::Done) return kRunEnded;
    return mode == Mode::Idle ? kGoalReached : Beep{};
  }

 private:
  uint8_t finishes_ = 0;
  protocol::BrickMode mode_ = protocol::BrickMode::Idle;
};

}  // namespace nxtmap::fw
