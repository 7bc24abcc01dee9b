// AvrModel: the ATmega48 co-processor as seen over TWI (7-bit address 1). Checks the 47-byte copyright
// handshake, accepts 9-byte frames (power, PWM frequency, 4 motor powers, brake mask, input power,
// checksum) and answers 13-byte frames (4 A/D values, buttons, battery, checksum). nxt-hardware.md 3.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace nxtmap::emu {

class AvrModel {
 public:
  static constexpr uint8_t kAddress = 1;
  // Delivered at the end of a TWI write (STOP).
  void receive(const std::vector<uint8_t>& frame);
  // The 13 bytes a read returns now (checksum included).
  std::array<uint8_t, 13> reply() const;

  bool handshakeDone() const { return handshake_; }
  int motorPower(int motor) const { return power_[static_cast<std::size_t>(motor)]; }  // -100..100, 0 if no handshake
  bool brake(int motor) const { return (mode_ >> motor) & 1u; }
  // Input power for sensor port 0..3: 9 V constant (0x10<<n) or pulsed (0x01<<n).
  bool sensorPowered(int port) const { return ((inputPower_ >> port) & 0x11u) != 0; }
  bool powerDownRequested() const { return powerDown_; }
  uint64_t goodFrames() const { return good_; }
  uint64_t badFrames() const { return bad_; }

  void setButtons(uint16_t raw) { buttons_ = raw; }
  void setBatteryMv(int mv) { batteryMv_ = mv; }

 private:
  bool handshake_ = false;
  std::array<int8_t, 4> power_{};
  uint8_t mode_ = 0;
  uint8_t inputPower_ = 0;
  bool powerDown_ = false;
  uint64_t good_ = 0, bad_ = 0;
  uint16_t buttons_ = 0;
  int batteryMv_ = 7800;
};

}  // namespace nxtmap::emu
