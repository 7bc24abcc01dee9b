#pragma once
#include <cstdint>

#include "common/protocol/LegoBrick.hpp"

namespace nxtmap::fw {

// Outputs A..C as a PC drives them with LEGO's SET_OUTPUT_STATE and RESET_MOTOR_POSITION while the
// robot rests. The power is applied as given (no speed regulation or synchronisation: those fields
// are kept and reported only); a tacho limit stops the output, braked, once it has turned that far.
// Counts are the tachometers' (degrees), passed in by the caller. ModeMachine owns it and drops
// every output when the robot starts moving.
class PcOutputs {
 public:
  static constexpr uint8_t kOutputs = protocol::kLegoOutputs;

  void set(const protocol::LegoOutputCommand& c, int32_t count) {
    Output& o = out_[c.port % kOutputs];
    o.cmd = c;
    o.tachoOrigin = count;
  }
  void resetPosition(uint8_t port, bool relative, int32_t count) {
    Output& o = out_[port % kOutputs];
    (relative ? o.blockOrigin : o.rotationOrigin) = count;
  }
  // The power for `port` now, -100..100; a reached tacho limit ends the run (run state idle).
  int8_t power(uint8_t port, int32_t count) {
    Output& o = out_[port % kOutputs];
    if (!running(o)) return 0;
    const int32_t turned = count - o.tachoOrigin;
    if (o.cmd.tachoLimit != 0 && static_cast<uint32_t>(turned < 0 ? -turned : turned) >= o.cmd.tachoLimit) {
      o.cmd.runState = protocol::kLegoRunIdle;
      o.cmd.mode = static_cast<uint8_t>(o.cmd.mode | protocol::kLegoBrake);
      return 0;
    }
    return o.cmd.power;
  }
  // Whether `port` rests braked (the default) rather than coasting (a PC's mode without kLegoBrake).
  bool brakes(uint8_t port) const {
    const Output& o = out_[port % kOutputs];
    return o.cmd.mode == 0 || (o.cmd.mode & protocol::kLegoBrake) != 0;
  }
  bool driven() const { return running(out_[0]) || running(out_[1]) || running(out_[2]); }
  // Every output off and braked (a run starts, a fault); the counters stay.
  void stopAll() {
    for (Output& o : out_) o.cmd = protocol::LegoOutputCommand{};
  }
  // As GET_OUTPUT_STATE reports it; `power` is what the output is driven with now.
  protocol::LegoOutputState state(uint8_t port, int32_t count, int8_t power) const {
    const Output& o = out_[port % kOutputs];
    protocol::LegoOutputState s;
    s.power = power;
    s.mode = o.cmd.mode;
    s.regulation = o.cmd.regulation;
    s.turnRatio = o.cmd.turnRatio;
    s.runState = power != 0 ? protocol::kLegoRunRunning : o.cmd.runState;
    s.tachoLimit = o.cmd.tachoLimit;
    s.tachoCount = count - o.tachoOrigin;
    s.blockTachoCount = count - o.blockOrigin;
    s.rotationCount = count - o.rotationOrigin;
    return s;
  }

 private:
  struct Output {
    protocol::LegoOutputCommand cmd;  // port, power, mode, regulation, turn, run state, limit
    int32_t tachoOrigin = 0, blockOrigin = 0, rotationOrigin = 0;  // counts at the last set / resets
  };
  static bool running(const Output& o) {
    return o.cmd.power != 0 && (o.cmd.mode & protocol::kLegoMotorOn) != 0 && o.cmd.runState != protocol::kLegoRunIdle;
  }

  Output out_[kOutputs];
};

}  // namespace nxtmap::fw
