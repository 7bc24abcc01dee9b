// Probe: an interrupt becomes pending at a store (the AIC's software set, ISCR) with IRQs enabled, followed by
// two stores to a marker in the same straight-line block. The handler reports the marker it saw: the value
// of the first store means the IRQ came one instruction after the one that raised it (the ARM7's latency),
// the second's means the end of the block, the one before means at once. Then the same with the TWI:
// enabling TXRDY's interrupt (TWI_IER) while the TWI is idle.
#include "Probe.hpp"
using namespace probe;

namespace {
constexpr uint32_t kAicIccr = 0xFFFFF128, kAicIscr = 0xFFFFF12C;
constexpr uint32_t kTwiIer = kTwi + 0x24, kTwiIdr = kTwi + 0x28;
volatile uint32_t g_marker;
volatile uint32_t g_seen;

// *reg = bit, then g_marker = first, then g_marker = second: three Thumb stores in a row.
void raiseThenMark(uint32_t reg, uint32_t bit, uint32_t first, uint32_t second) {
  asm volatile(
      "str %1, [%0]\n\t"
      "str %3, [%2]\n\t"
      "str %4, [%2]\n\t"
      :
      : "l"(reg), "l"(bit), "l"(&g_marker), "l"(first), "l"(second)
      : "memory");
}
}  // namespace

extern "C" void soft_isr() {
  g_seen = g_marker;
  REG(kAicIccr) = 1u << 10;
}

extern "C" void twi_isr() {
  g_seen = g_marker;
  REG(kTwiIdr) = 4;
}

int main() {
  REG(kWdtMr) = 1u << 15;
  REG(kAicSvr + 4 * 10) = reinterpret_cast<uint32_t>(&soft_isr);
  REG(kAicSmr + 4 * 10) = 1;
  REG(kAicSvr + 4 * 9) = reinterpret_cast<uint32_t>(&twi_isr);
  REG(kAicSmr + 4 * 9) = 2;
  REG(kAicIecr) = (1u << 10) | (1u << 9);
  twiInit();
  irq_enable();

  g_marker = 1;
  raiseThenMark(kAicIscr, 1u << 10, 2, 3);
  report(g_seen);

  g_marker = 4;
  raiseThenMark(kTwiIer, 4, 5, 6);  // TXRDY is set while the TWI is idle
  report(g_seen);
  print("irq ok\n");
  return 0;
}
