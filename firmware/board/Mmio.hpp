#pragma once
#include <cstdint>

namespace nxtmap::fw {

// The real register backend of the drivers: 32-bit volatile accesses at absolute addresses.
// Host tests use a fake with the same three members (tests/firmware/FakeBus.hpp).
struct Mmio {
  static uint32_t read(uint32_t addr) { return *reinterpret_cast<volatile uint32_t*>(addr); }
  static void write(uint32_t addr, uint32_t value) { *reinterpret_cast<volatile uint32_t*>(addr) = value; }
  static uint32_t address(const void* p) { return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(p)); }
};

}  // namespace nxtmap::fw
