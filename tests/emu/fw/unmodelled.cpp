// Broken on purpose: reads a register of a peripheral the emulator does not model (the USB device port).
#include "Probe.hpp"

int main() {
  REG(probe::kWdtMr) = 1u << 15;
  return static_cast<int>(REG(0xFFFB0000u + 0x1C));  // UDP_ISR
}
