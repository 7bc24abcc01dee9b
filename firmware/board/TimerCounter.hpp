#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"

namespace nxtmap::fw {

// Timer/counter channel 0 as a periodic interrupt that can be started and stopped (the soft I2C
// bit clock of the sensor ports): counts MCK/2, an interrupt and a reset at each RC compare.
template <class Bus>
class TimerCounter {
 public:
  explicit TimerCounter(Bus& bus) : bus_(bus) {}

  // RC for `hz` interrupts per second at master clock `mck` (Hz).
  static constexpr uint32_t rcFor(uint32_t mck, uint32_t hz) { return mck / 2 / hz; }

  // Stopped, with its period set to `rc` MCK/2 counts and the RC compare interrupt on. The clock is
  // the caller's (Pmc::enable(reg::kIdTc0)).
  void init(uint32_t rc) {
    using namespace reg;
    bus_.write(kTc0Ccr, kTcCcrClkdis);
    bus_.write(kTc0Cmr, kTcCmrTimerClock1 | kTcCmrCpctrg);
    bus_.write(kTc0Rc, rc);
    bus_.write(kTc0Ier, kTcSrCpcs);
  }
  // Counts from 0 (first interrupt one period from now).
  void start() { bus_.write(reg::kTc0Ccr, reg::kTcCcrClken | reg::kTcCcrSwtrg); }
  void stop() { bus_.write(reg::kTc0Ccr, reg::kTcCcrClkdis); }
  // Clears the pending compare (the interrupt handler's first read).
  void acknowledge() { (void)bus_.read(reg::kTc0Sr); }

 private:
  Bus& bus_;
};

}  // namespace nxtmap::fw
