// Shared helpers of the emulator's probe programs (freestanding, ARM7TDMI Thumb): register access,
// the test port, PIT-based delays, a polled TWI link to the AVR.
#pragma once
#include <stdint.h>

#define REG(a) (*reinterpret_cast<volatile uint32_t*>(static_cast<uintptr_t>(a)))

namespace probe {
constexpr uint32_t kTestPut = 0xFFFE8000, kTestValue = 0xFFFE8004;
constexpr uint32_t kAicSmr = 0xFFFFF000, kAicSvr = 0xFFFFF080, kAicIecr = 0xFFFFF120, kAicIdcr = 0xFFFFF124;
constexpr uint32_t kPmcScdr = 0xFFFFFC04, kPmcPcer = 0xFFFFFC10;
constexpr uint32_t kPitMr = 0xFFFFFD30, kPitPivr = 0xFFFFFD38, kPitPiir = 0xFFFFFD3C;
constexpr uint32_t kWdtMr = 0xFFFFFD44;
constexpr uint32_t kPio = 0xFFFFF400;
constexpr uint32_t kPer = kPio + 0x00, kPdr = kPio + 0x04, kOer = kPio + 0x10, kOdr = kPio + 0x14, kSodr = kPio + 0x30,
                   kCodr = kPio + 0x34, kPdsr = kPio + 0x3C, kIer = kPio + 0x40, kIsr = kPio + 0x4C,
                   kPpudr = kPio + 0x60, kAsr = kPio + 0x70;
constexpr uint32_t kTwi = 0xFFFB8000;
constexpr uint32_t kTwiCr = kTwi, kTwiMmr = kTwi + 0x04, kTwiCwgr = kTwi + 0x10, kTwiSr = kTwi + 0x20,
                   kTwiRhr = kTwi + 0x30, kTwiThr = kTwi + 0x34;

inline void report(uint32_t v) { REG(kTestValue) = v; }
inline void print(const char* s) {
  while (*s) REG(kTestPut) = static_cast<uint8_t>(*s++);
}

// Free-running PIT at 1 ms periods (no interrupt); waits by polling PIIR (time advances per block).
inline void pitStart() { REG(kPitMr) = 3002u | (1u << 24); }
inline void waitMs(uint32_t ms) {
  (void)REG(kPitPivr);
  uint32_t seen = 0;
  while (seen < ms) seen += REG(kPitPivr) >> 20;
}

// The AVR link, polled: handshake, then one command frame and one status frame per call.
inline void twiInit() {
  REG(kPmcPcer) = (1u << 9) | (1u << 2);
  REG(kPdr) = (1u << 3) | (1u << 4);
  REG(kAsr) = (1u << 3) | (1u << 4);
  REG(kTwiCr) = 0x80;
  REG(kTwiCwgr) = 57u | (57u << 8);
  REG(kTwiCr) = 0x04;
}
inline bool twiWrite(const uint8_t* b, int n) {
  REG(kTwiMmr) = 1u << 16;
  for (int i = 0; i < n; ++i) {
    while (!(REG(kTwiSr) & 4)) {}
    REG(kTwiThr) = b[i];  // the first byte starts the frame; STOP follows by itself once THR runs dry
  }
  uint32_t sr;
  while (!((sr = REG(kTwiSr)) & 1)) {}
  return !(sr & (1u << 8));
}
inline bool twiRead(uint8_t* b, int n) {
  REG(kTwiMmr) = (1u << 16) | (1u << 12);
  REG(kTwiCr) = 1;
  for (int i = 0; i < n; ++i) {
    uint32_t sr;
    while (!((sr = REG(kTwiSr)) & 2)) {
      if (sr & (1u << 8)) return false;
    }
    b[i] = static_cast<uint8_t>(REG(kTwiRhr));
    if (i == n - 2) REG(kTwiCr) = 2;
  }
  while (!(REG(kTwiSr) & 1)) {}
  return true;
}
inline bool avrHandshake() {
  static const char kText[] = "Let's samba nxt arm in arm, (c)LEGO System A/S";
  uint8_t b[47];
  b[0] = 0xCC;
  for (int i = 0; i < 46; ++i) b[i + 1] = static_cast<uint8_t>(kText[i]);
  return twiWrite(b, 47);
}
inline bool avrCommand(int8_t a, int8_t bPow, int8_t c, uint8_t brake, uint8_t inputPower) {
  uint8_t f[9] = {0,          8, static_cast<uint8_t>(a), static_cast<uint8_t>(bPow), static_cast<uint8_t>(c), 0, brake,
                  inputPower, 0};
  unsigned sum = 0;
  for (int i = 0; i < 8; ++i) sum += f[i];
  f[8] = static_cast<uint8_t>(~sum);
  return twiWrite(f, 9);
}
}  // namespace probe

extern "C" void irq_enable();
extern "C" void irq_disable();
