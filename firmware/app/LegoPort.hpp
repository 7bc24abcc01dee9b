#pragma once
#include <cstdint>

#include "common/protocol/LegoBrick.hpp"
#include "firmware/app/ActionRunner.hpp"
#include "firmware/app/ModeMachine.hpp"

namespace nxtmap::fw {

// LEGO's direct commands as the brick carries them out (the BrickLink's LegoBrick): the outputs
// through the ModeMachine (obeyed while the robot rests, through the same MotorSafety), the
// ultrasonic ports' last readings from the ActionRunner. No speaker driver yet: tones are
// answered and not played. Both parts are BrickApp's.
class LegoPort final : public protocol::LegoBrick {
 public:
  LegoPort(ModeMachine& modes, const ActionRunner& runner) : modes_(modes), runner_(runner) {}

  protocol::LegoOutputState output(uint8_t port) const override { return modes_.output(port); }
  // Every port holds an ultrasonic sensor: LEGO's LOW_SPEED_9V type, the reading in cm as the
  // scaled value (255: no echo), valid once the port has been read.
  protocol::LegoInputValues input(uint8_t port) const override {
    protocol::LegoInputValues v;
    v.sensorType = protocol::kLegoLowSpeed9V;
    uint8_t cm = 0;
    v.valid = runner_.lastReading(port, cm);
    v.raw = v.normalized = cm;
    v.scaled = v.calibrated = cm;
    return v;
  }
  uint8_t setOutput(const protocol::LegoOutputCommand& c) override { return modes_.setOutput(c); }
  uint8_t resetPosition(uint8_t port, bool relative) override { return modes_.resetPosition(port, relative); }

 private:
  ModeMachine& modes_;
  const ActionRunner& runner_;
};

}  // namespace nxtmap::fw
