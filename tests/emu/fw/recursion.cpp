// Broken on purpose: runaway recursion grows the stack until it leaves its area.
#include "Probe.hpp"

volatile uint32_t g_limit = 0xFFFFFFFFu;  // never reached: the recursion only looks bounded

__attribute__((noinline)) uint32_t deeper(uint32_t n) {
  volatile uint8_t local[64];
  local[0] = static_cast<uint8_t>(n);
  if (n >= g_limit) return local[0];
  return deeper(n + 1) + local[0];
}

int main() {
  REG(probe::kWdtMr) = 1u << 15;
  return static_cast<int>(deeper(0));
}
