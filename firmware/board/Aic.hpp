#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"

namespace nxtmap::fw {

using IrqHandler = void (*)();

// The advanced interrupt controller: no protect mode, no nesting (each handler is an ARM
// `interrupt("IRQ")` function entered through AIC_IVR that ends with a write to AIC_EOICR).
template <class Bus>
class Aic {
 public:
  explicit Aic(Bus& bus) : bus_(bus) {}

  void init(uint32_t spuriousAddress) {
    using namespace reg;
    bus_.write(kAicIdcr, ~0u);
    bus_.write(kAicIccr, ~0u);
    bus_.write(kAicFfdr, ~0u);
    for (int i = 0; i < 8; ++i) bus_.write(kAicEoicr, 1u);  // unwind any in-service levels
    bus_.write(kAicDcr, 0u);
    bus_.write(kAicSpu, spuriousAddress);
  }
  // How an internal source interrupts: while its line is high (Level), or once per rising edge (Edge,
  // latched by the AIC and cleared when IVR hands it out).
  enum class Trigger : uint8_t { Level = 0, Edge = 1u << 5 };  // SMR SRCTYPE, bits 5-6
  // Internal source `id` at `priority` (0..7, 7 highest), handler at `address`.
  void install(uint32_t id, uint32_t priority, uint32_t address, Trigger trigger = Trigger::Level) {
    using namespace reg;
    bus_.write(kAicIdcr, 1u << id);
    bus_.write(kAicSmr + 4 * id, (priority & 7u) | static_cast<uint32_t>(trigger));
    bus_.write(kAicSvr + 4 * id, address);
    bus_.write(kAicIccr, 1u << id);
    bus_.write(kAicIecr, 1u << id);
  }
  void endOfInterrupt() { bus_.write(reg::kAicEoicr, 0u); }

 private:
  Bus& bus_;
};

extern "C" {
uint32_t nxtmapIrqEnable();   // clears CPSR.I (ARM helper in Startup.S)
uint32_t nxtmapIrqDisable();  // sets CPSR.I, returns the previous CPSR
}

}  // namespace nxtmap::fw
