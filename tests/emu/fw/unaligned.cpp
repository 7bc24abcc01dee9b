// Broken on purpose: a word load from an odd address (the ARM7TDMI would rotate it, the SAM7S aborts).
#include "Probe.hpp"

volatile uint8_t g_bytes[8] = {1, 2, 3, 4, 5, 6, 7, 8};

int main() {
  REG(probe::kWdtMr) = 1u << 15;
  volatile uint32_t* p = reinterpret_cast<volatile uint32_t*>(reinterpret_cast<uintptr_t>(&g_bytes[1]));
  probe::report(reinterpret_cast<uint32_t>(p));
  uint32_t v;
  asm volatile("ldr %0, [%1]" : "=l"(v) : "l"(p) : "memory");  // the compiler would split a visible misaligned load
  return static_cast<int>(v);
}
