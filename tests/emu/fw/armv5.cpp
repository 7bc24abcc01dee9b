// Broken on purpose: a BLX (ARMv5T) in Thumb code; the ARM7TDMI (ARMv4T) has no BLX.
#include "Probe.hpp"

extern "C" int target() { return 3; }

int main() {
  REG(probe::kWdtMr) = 1u << 15;
  int (*volatile fn)() = &target;
  int r;
  asm volatile("mov r0, %1\n\t.inst.n 0x4780\n\tmov %0, r0" : "=r"(r) : "r"(fn) : "r0", "r1", "r2", "r3", "lr");
  return r;
}
