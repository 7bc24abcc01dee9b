#pragma once
#include <cstdint>

namespace nxtmap::fw {

// The compiler keeps every memory access of the program on its side of this point (it emits nothing):
// the ARM7TDMI has no cache and no write buffer to drain, so ordering the compiler's accesses is all
// ordering takes.
inline void compilerBarrier() { asm volatile("" ::: "memory"); }

// The real register backend of the drivers: 32-bit volatile accesses at absolute addresses.
// Host tests use a fake with the same three members (tests/firmware/FakeBus.hpp).
// Each access is also a compiler barrier (as Linux's readl/writel): a PDC channel reads and writes RAM
// the compiler cannot see, so the bytes a driver stores before it starts a transfer must be in RAM when the
// register write starts it, and the bytes it loads after reading a counter must be loaded after that read
// (with link-time optimisation every driver is inlined into its callers and could otherwise be reordered).
struct Mmio {
  static uint32_t read(uint32_t addr) {
    const uint32_t v = *reinterpret_cast<volatile uint32_t*>(addr);
    compilerBarrier();
    return v;
  }
  static void write(uint32_t addr, uint32_t value) {
    compilerBarrier();
    *reinterpret_cast<volatile uint32_t*>(addr) = value;
  }
  static uint32_t address(const void* p) { return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(p)); }
};

}  // namespace nxtmap::fw
