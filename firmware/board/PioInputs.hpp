#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"

namespace nxtmap::fw {

// PIO A pins read as inputs with change interrupts (the motors' tachometer lines). Pins are masks
// of reg::pin(n). The controller's clock is the caller's (Pmc::enable(reg::kIdPioa)).
template <class Bus>
class PioInputs {
 public:
  explicit PioInputs(Bus& bus) : bus_(bus) {}

  // No PIO A pin interrupts until interruptOnChange().
  void disableInterrupts() { bus_.write(reg::kPioIdr, ~0u); }
  // `pins` become PIO inputs with the glitch filter (pulses under half an MCK cycle dropped) and
  // without the pull-ups (the board drives them).
  void filteredInputs(uint32_t pins) {
    bus_.write(reg::kPioIfer, pins);
    bus_.write(reg::kPioPpudr, pins);
    bus_.write(reg::kPioPer, pins);
    bus_.write(reg::kPioOdr, pins);
  }
  // An interrupt on every level change of `pins`; changes seen before are dropped.
  void interruptOnChange(uint32_t pins) {
    (void)bus_.read(reg::kPioIsr);
    bus_.write(reg::kPioIer, pins);
  }
  // The pins that changed since the last call (reading clears them and the interrupt).
  uint32_t takeChanges() { return bus_.read(reg::kPioIsr); }
  // The level of every pin now.
  uint32_t levels() const { return bus_.read(reg::kPioPdsr); }

 private:
  Bus& bus_;
};

}  // namespace nxtmap::fw
