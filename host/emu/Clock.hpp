// Clock: the emulated brick's time base. One executed instruction = one MCK cycle (CPI 1), so the
// instruction count is the clock. Shared by the machine (which advances it) and every peripheral model.
#pragma once

#include <cstdint>
#include <limits>

namespace nxtmap::emu {

constexpr uint64_t kMckHz = 48054857;  // 18.432 MHz x 73 / 14 / 2 (nxt-hardware.md 1.4)
constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();

// Instruction counts for a duration (rounded down), and back.
constexpr uint64_t cyclesFromUs(uint64_t us) { return us * kMckHz / 1000000u; }
constexpr uint64_t cyclesFromMs(uint64_t ms) { return ms * kMckHz / 1000u; }
inline double secondsFromCycles(uint64_t cycles) { return static_cast<double>(cycles) / static_cast<double>(kMckHz); }

// The slow clock (SLCK) is the SAM7S's internal RC oscillator: 22..42 kHz across parts, voltage and
// temperature (datasheet electrical characteristics), 32.768 kHz only nominally. A run draws its value
// from the range with its seed, so timing that holds only at 32.768 kHz fails somewhere.
constexpr uint32_t kSlowClockMinHz = 22000, kSlowClockMaxHz = 42000;
constexpr uint32_t slowClockHzForSeed(uint64_t seed) {
  uint64_t x = seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;  // splitmix64 finaliser
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  x ^= x >> 31;
  return kSlowClockMinHz + static_cast<uint32_t>(x % (kSlowClockMaxHz - kSlowClockMinHz + 1));
}

struct Clock {
  uint64_t now = 0;                              // cycles since reset
  uint64_t stopAt = 0;                           // the machine stops at the first block boundary with now >= stopAt
  uint32_t slowClockHz = slowClockHzForSeed(0);  // SLCK of this brick, kSlowClockMinHz..kSlowClockMaxHz
  // A model changed interrupt or timing state: re-plan at the next block boundary.
  void poke() { stopAt = 0; }
};

}  // namespace nxtmap::emu
