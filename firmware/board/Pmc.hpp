#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"

namespace nxtmap::fw {

// The power management controller after start-up (LowLevelInit.cpp set the clocks): peripheral
// clocks on, and the processor clock off until the next interrupt (the idle loop).
template <class Bus>
class Pmc {
 public:
  explicit Pmc(Bus& bus) : bus_(bus) {}

  // Clock on for peripheral `id` (a reg::PeripheralId); its registers do nothing without it.
  void enable(uint32_t id) { bus_.write(reg::kPmcPcer, reg::peripheralBit(id)); }
  // Stops the processor until an interrupt (enabled in the AIC) is pending; peripherals run on.
  void idle() { bus_.write(reg::kPmcScdr, reg::kPmcScdrPck); }

 private:
  Bus& bus_;
};

}  // namespace nxtmap::fw
