// The mode machine's motor outputs: the powers and brakes set every tick (the robot's own run takes the motors,
// otherwise the PC's direct commands hold them), and the PC's LEGO output commands (refused while the robot moves).
#include "firmware/app/ModeMachine.hpp"

namespace nxtmap::fw {

void ModeMachine::driveMotors() {
  if (safety_.tripped()) return;
  const bool run = moving();
  if (run) pc_.stopAll();  // the robot's own run takes the motors
  uint8_t brake = kAllBrakes;
  for (uint8_t p = 0; p < PcOutputs::kOutputs; ++p) {
    int8_t v = pc_.power(p, tacho_.count(p));
    if (run) v = p == config_.leftMotor ? runner_.power(0) : p == config_.rightMotor ? runner_.power(1) : int8_t{0};
    motors_.pwm[p] = v;
    if (v != 0 || (!run && !pc_.brakes(p))) brake = static_cast<uint8_t>(brake & ~(1u << p));
  }
  motors_.brakeMask = brake;
}

uint8_t ModeMachine::setOutput(const protocol::LegoOutputCommand& c) {
  if (moving() || safety_.tripped() || c.port >= PcOutputs::kOutputs) return protocol::kLegoRequestFailed;
  pc_.set(c, tacho_.count(c.port));
  return protocol::kLegoOk;
}

uint8_t ModeMachine::resetPosition(uint8_t port, bool relative) {
  if (moving() || port >= PcOutputs::kOutputs) return protocol::kLegoRequestFailed;
  pc_.resetPosition(port, relative, tacho_.count(port));
  return protocol::kLegoOk;
}

protocol::LegoOutputState ModeMachine::output(uint8_t port) const {
  const uint8_t p = port % PcOutputs::kOutputs;
  return pc_.state(p, tacho_.count(p), motors_.pwm[p]);
}

}  // namespace nxtmap::fw
