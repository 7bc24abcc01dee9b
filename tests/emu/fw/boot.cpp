// Probe: start-up (static constructor, .data), remap of RAM to address 0, a 1 kHz PIT interrupt through
// the AIC, and idling with the processor clock stopped until 100 ticks have passed.
#include "Probe.hpp"
using namespace probe;

namespace {
struct Ctor {
  uint32_t v;
  Ctor() : v(0xC0FFEEu) {}
};
Ctor g_ctor;
uint32_t g_data = 0x12345678u;
volatile uint32_t g_ticks;
}  // namespace

extern "C" void pit_isr() { g_ticks = g_ticks + (REG(kPitPivr) >> 20); }

int main() {
  REG(kWdtMr) = 1u << 15;
  report(g_ctor.v);
  report(g_data);
  // Remap: copy the vectors to RAM, toggle RCB when RAM is not yet at 0, check that 0 now shows RAM.
  for (uint32_t i = 0; i < 64; i += 4) REG(0x200000 + i) = REG(0x100000 + i);
  REG(0x200000 + 60) = 0xA11CE5u;  // a marker in the RAM copy's unused last literal slot
  const bool before = REG(60) == 0xA11CE5u;
  if (!before) REG(0xFFFFFF00) = 1;
  report(before ? 1u : 0u);
  report(REG(60));
  REG(kAicSvr + 4) = reinterpret_cast<uint32_t>(&pit_isr);
  REG(kAicSmr + 4) = 1;
  REG(kAicIecr) = 1u << 1;
  REG(kPitMr) = 3002u | (3u << 24);
  irq_enable();
  while (g_ticks < 100) REG(kPmcScdr) = 1;
  report(g_ticks);
  print("boot ok\n");
  return 7;
}
