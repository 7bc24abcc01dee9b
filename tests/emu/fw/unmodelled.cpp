// Broken on purpose: reads a register of a peripheral the emulator does not model (the debug unit, whose pins
// the NXT uses for other things).
#include "Probe.hpp"

int main() {
  REG(probe::kWdtMr) = 1u << 15;
  return static_cast<int>(REG(0xFFFFF200u + 0x40));  // DBGU_CIDR
}
