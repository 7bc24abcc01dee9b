#pragma once
#include <cstdint>

#include "common/protocol/LegoFormat.hpp"

namespace nxtmap::protocol {

// One output as GET_OUTPUT_STATE reports it (LEGO's fields; counts in degrees).
struct LegoOutputState {
  int8_t power = 0;  // -100..100, as driven now
  uint8_t mode = 0;  // kLegoMotorOn | kLegoBrake | kLegoRegulated
  uint8_t regulation = 0;
  int8_t turnRatio = 0;
  uint8_t runState = kLegoRunIdle;
  uint32_t tachoLimit = 0;      // 0: run for ever
  int32_t tachoCount = 0;       // since the last SET_OUTPUT_STATE
  int32_t blockTachoCount = 0;  // since the last RESET_MOTOR_POSITION(relative)
  int32_t rotationCount = 0;    // since power-on or RESET_MOTOR_POSITION(absolute)
};

// One input as GET_INPUT_VALUES reports it.
struct LegoInputValues {
  bool valid = false;
  uint8_t sensorType = 0;  // 0: no sensor
  uint8_t sensorMode = kLegoRawMode;
  uint16_t raw = 0, normalized = 0;
  int16_t scaled = 0, calibrated = 0;
};

// SET_OUTPUT_STATE for one output (port 0..2).
struct LegoOutputCommand {
  uint8_t port = 0;
  int8_t power = 0;
  uint8_t mode = 0, regulation = 0;
  int8_t turnRatio = 0;
  uint8_t runState = kLegoRunIdle;
  uint32_t tachoLimit = 0;
};

// What LEGO's direct commands read from the brick and do to it: the firmware's outputs, inputs,
// speaker and radio, behind one seam (BrickLink::attach). The link checks ports and refuses motor
// commands while the robot moves before it calls in here. The defaults are a brick with nothing
// attached: outputs and inputs empty, motor commands refused (kLegoRequestFailed), tones silent.
class LegoBrick {
 public:
  virtual LegoOutputState output(uint8_t /*port 0..2*/) const { return LegoOutputState{}; }
  virtual LegoInputValues input(uint8_t /*port 0..3*/) const { return LegoInputValues{}; }
  // LEGO's status for the command (kLegoOk when carried out).
  virtual uint8_t setOutput(const LegoOutputCommand& /*c*/) { return kLegoRequestFailed; }
  virtual uint8_t resetPosition(uint8_t /*port 0..2*/, bool /*relative*/) { return kLegoRequestFailed; }
  virtual void playTone(uint16_t /*hz*/, uint16_t /*ms*/) {}
  virtual void stopSound() {}
  // The brick's Bluetooth address, most significant byte first (zeros: unknown).
  virtual void address(uint8_t (&a)[6]) const {
    for (uint8_t& b : a) b = 0;
  }
  // Flash left above the firmware image, bytes (LEGO: free user flash; default 0).
  virtual uint32_t freeFlashBytes() const { return 0; }

 protected:
  LegoBrick() = default;
  LegoBrick(const LegoBrick&) = default;
  LegoBrick& operator=(const LegoBrick&) = default;
  ~LegoBrick() = default;
};

// The brick with nothing attached (BrickLink's default).
class NoLegoBrick final : public LegoBrick {};

}  // namespace nxtmap::protocol
