// Broken on purpose: forgets to disable the watchdog and idles forever with the PIT running.
#include "Probe.hpp"
using namespace probe;

extern "C" void pit_isr() { (void)REG(kPitPivr); }

int main() {
  REG(kAicSvr + 4) = reinterpret_cast<uint32_t>(&pit_isr);
  REG(kAicIecr) = 1u << 1;
  REG(kPitMr) = 3002u | (3u << 24);
  irq_enable();
  for (;;) REG(kPmcScdr) = 1;
}
