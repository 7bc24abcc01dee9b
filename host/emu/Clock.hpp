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

struct Clock {
  uint64_t now = 0;     // cycles since reset
  uint64_t stopAt = 0;  // the machine stops at the first block boundary with now >= stopAt
  // A model changed interrupt or timing state: re-plan at the next block boundary.
  void poke() { stopAt = 0; }
};

}  // namespace nxtmap::emu
