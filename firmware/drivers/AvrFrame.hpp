#pragma once
#include <cstdint>

// The ARM <-> AVR (ATmega48) frames on the TWI link: pure packing, checksums and decoding.
// Layouts: nxt-hardware facts sections 3.2-3.4 (LEGO m_sched.h IOTOAVR / IOFROMAVR).
namespace nxtmap::fw {

// The byte-exact handshake: 0xCC then the 46 ASCII bytes (no space in "(c)LEGO").
constexpr char kAvrCopyright[] = "Let's samba nxt arm in arm, (c)LEGO System A/S";
constexpr uint8_t kAvrHandshakeBytes = 47;
constexpr uint8_t kAvrAddress = 1;  // 7-bit TWI slave address
constexpr uint8_t kAvrTxBytes = 9;
constexpr uint8_t kAvrRxBytes = 13;

// What the ARM asks of the AVR (one 9-byte frame).
struct AvrCommand {
  uint8_t power = 0;             // 0 normal, 0x5A power down, 0xA5 (+ pwmFreq 0x5A) SAM-BA
  uint8_t pwmFreq = 8;           // motor PWM in kHz, 1..32
  int8_t pwm[4] = {0, 0, 0, 0};  // motors A, B, C, (unused) in -100..100 %
  uint8_t brakeMask = 0;         // bit n: 1 brake, 0 coast (float), motor n
  uint8_t inputPower = 0;        // bit n: pulsed 9 V, bit n+4: constant 9 V, sensor port n
};

// Sets constant 9 V on sensor port n (0..3): the ultrasonic sensor's supply.
constexpr uint8_t constant9v(int port) { return static_cast<uint8_t>(0x10u << port); }

inline void packAvrHandshake(uint8_t out[kAvrHandshakeBytes]) {
  out[0] = 0xCC;
  for (uint8_t i = 0; i < kAvrHandshakeBytes - 1; ++i) out[i + 1] = static_cast<uint8_t>(kAvrCopyright[i]);
}

// out[8] = ~(sum of out[0..7]); the AVR accepts when all 9 bytes sum to 0xFF.
inline void packAvrCommand(const AvrCommand& c, uint8_t out[kAvrTxBytes]) {
  out[0] = c.power;
  out[1] = c.pwmFreq;
  for (int i = 0; i < 4; ++i) {
    int v = c.pwm[i];
    if (v > 100) v = 100;
    if (v < -100) v = -100;
    out[2 + i] = static_cast<uint8_t>(static_cast<int8_t>(v));
  }
  out[6] = c.brakeMask;
  out[7] = c.inputPower;
  uint8_t sum = 0;
  for (int i = 0; i < 8; ++i) sum = static_cast<uint8_t>(sum + out[i]);
  out[8] = static_cast<uint8_t>(~sum);
}

// What the AVR reports (one 13-byte frame).
struct AvrStatus {
  uint16_t analog[4] = {0, 0, 0, 0};  // raw 10-bit A/D of sensor pin 1, ports 1..4
  uint16_t buttonsRaw = 0;            // button ladder A/D, +0x7FF while Enter is down
  uint16_t batteryRaw = 0;            // bits 0-9 A/D, bit 15 rechargeable pack
};

// Decodes a received frame; false (and `out` unchanged) when the 13 bytes do not sum to 0xFF.
inline bool parseAvrStatus(const uint8_t in[kAvrRxBytes], AvrStatus& out) {
  uint8_t sum = 0;
  for (int i = 0; i < kAvrRxBytes; ++i) sum = static_cast<uint8_t>(sum + in[i]);
  if (sum != 0xFF) return false;
  auto le16 = [in](int at) { return static_cast<uint16_t>(in[at] | (in[at + 1] << 8)); };
  for (int i = 0; i < 4; ++i) out.analog[i] = le16(2 * i);
  out.buttonsRaw = le16(8);
  out.batteryRaw = le16(10);
  return true;
}

// Battery in millivolts: raw x 13.848 (LEGO's factor), in integers.
constexpr uint32_t batteryMillivolts(uint16_t batteryRaw) {
  return (static_cast<uint32_t>(batteryRaw & 0x3FFu) * 13848u) / 1000u;
}

enum class Button : uint8_t { None, Enter, Exit, Right, Left };

// The ladder thresholds (leJOS / NxOS): Enter adds 0x7FF; then exit > 720, right > 270, left > 60.
constexpr Button decodeButton(uint16_t raw) {
  if (raw > 1500) return Button::Enter;
  if (raw > 720) return Button::Exit;
  if (raw > 270) return Button::Right;
  if (raw > 60) return Button::Left;
  return Button::None;
}

}  // namespace nxtmap::fw
