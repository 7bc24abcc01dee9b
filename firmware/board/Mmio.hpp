#pragma once
#include <cstdint>

namespace nxtmap::fw {

// The compiler keeps every memory access of the program on its side of this point (it emits nothing):
// the ARM7TDMI has no cache and no write buffer to drain, so ordering the compiler's accesses is all
// ordering takes.
inline void compilerBarrier() { asm volatile("" ::: "memory"); }

// The real register backend of the drivers: 32-bit volatile accesses at absolute addresses.
// Host tests use a fake with the same three members (tests/firmware/FakeBus.hpp).
// A PDC channel reads and writes RAM the compiler cannot see: a driver puts compilerBarrier() between
// the stores of a buffer and the register write that starts its transfer, and between the counter read that
// says bytes arrived and the loads of them (with link-time optimisation every driver is inlined into its
// callers, and plain stores and loads may move across volatile accesses).
struct Mmio {
  static uint32_t read(uint32_t addr) { return *reinterpret_cast<volatile uint32_t*>(addr); }
  static void write(uint32_t addr, uint32_t value) { *reinterpret_cast<volatile uint32_t*>(addr) = value; }
  static uint32_t address(const void* p) { return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(p)); }
};

}  // namespace nxtmap::fw
