#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"

namespace nxtmap::fw {

// The system controller's periodic interval timer (PIT: the brick's millisecond tick, on the
// shared system interrupt) and its watchdog, restarted from the tick (LowLevelInit.cpp set the
// watchdog to 250 ms).
template <class Bus>
class SystemTimer {
 public:
  explicit SystemTimer(Bus& bus) : bus_(bus) {}

  // The PIT's period register for `hz` periods per second at master clock `mck` (Hz): it counts
  // MCK/16 and wraps after PIV + 1 counts (1 kHz at 48 MHz: 2002).
  static constexpr uint32_t periodValue(uint32_t mck, uint32_t hz) { return (mck / 16 / hz - 1) & reg::kPitMrPivMask; }

  // Periods of 1 / `hz` s with an interrupt at the end of each.
  void start(uint32_t mck, uint32_t hz) {
    bus_.write(reg::kPitMr, periodValue(mck, hz) | reg::kPitMrPiten | reg::kPitMrPitien);
  }
  // True when a period ended (the system interrupt may also come from another system peripheral).
  bool due() const { return (bus_.read(reg::kPitSr) & reg::kPitSrPits) != 0; }
  // Periods ended since the last call (>= 1 when due()); the read clears due().
  uint32_t takeElapsed() { return bus_.read(reg::kPitPivr) >> reg::kPitPivrPicntShift; }
  // Restarts the watchdog's count: a program that stops ticking resets the brick.
  void restartWatchdog() { bus_.write(reg::kWdtCr, reg::kWdtCrKey | reg::kWdtCrWdrstt); }

 private:
  Bus& bus_;
};

}  // namespace nxtmap::fw
