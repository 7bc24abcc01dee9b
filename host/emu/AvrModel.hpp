// AvrModel: the ATmega48 co-processor as seen over TWI (7-bit address 1), written from what its program
// does with a write: a first byte 0xCC starts the copyright string, matched byte by byte (the handshake is
// done once all 46 match; bytes after them are not looked at); any other frame's first 9 bytes (power, PWM
// frequency, 4 motor powers, brake mask, input power, checksum) are obeyed when they sum to 0xFF, with or
// without the handshake, and trailing bytes are not looked at. A frame that delivers nothing (short, a bad
// checksum, a wrong string) counts as bad. Reads answer 13 bytes (4 A/D values, buttons, battery,
// checksum). nxt-hardware.md 3.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace nxtmap::emu {

class AvrModel {
 public:
  static constexpr uint8_t kAddress = 1;
  static constexpr size_t kCommandBytes = 9;  // 8 data bytes and the checksum
  // Delivered at the end of a TWI write (STOP).
  void receive(const std::vector<uint8_t>& frame);
  // The 13 bytes a read returns now (checksum included).
  std::array<uint8_t, 13> reply() const;

  bool handshakeDone() const { return handshake_; }
  int motorPower(int motor) const { return power_[static_cast<std::size_t>(motor)]; }  // -100..100
  bool brake(int motor) const { return (mode_ >> motor) & 1u; }
  // Input power for sensor port 0..3: 9 V constant (0x10<<n) or pulsed (0x01<<n).
  bool sensorPowered(int port) const { return ((inputPower_ >> port) & 0x11u) != 0; }
  bool powerDownRequested() const { return powerDown_; }
  uint64_t goodFrames() const { return good_; }
  uint64_t badFrames() const { return bad_; }

  void setButtons(uint16_t raw) { buttons_ = raw; }
  void setBatteryMv(int mv) { batteryMv_ = mv; }

 private:
  void apply(const std::vector<uint8_t>& frame);
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
