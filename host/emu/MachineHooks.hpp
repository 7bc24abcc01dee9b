// MachineHooks: the Unicorn callbacks of a Machine (blocks, memory faults, exceptions, invalid instructions,
// the MMIO window, the timed function and, where Unicorn cannot check alignment, every load and store).
// Private to the machine's own files.
#pragma once

#include "host/emu/Machine.hpp"

#include <unicorn/unicorn.h>

#include <cstdint>
#include <string>

namespace nxtmap::emu {

constexpr uint64_t kMmioBase = 0xFFFA0000;
constexpr uint64_t kMmioSize = 0x60000;
constexpr uint32_t kCpsrT = 1u << 5, kCpsrI = 1u << 7;

std::string hexWord(uint32_t v);  // "0x0020f540"

struct Machine::Hooks {
  static void block(uc_engine* uc, uint64_t address, uint32_t size, void* user);
  [[gnu::noinline]] static void blockInFull(uc_engine* uc, uint64_t address, uint32_t size, void* user);
  static void timedEntry(uc_engine* uc, uint64_t, uint32_t, void* user);
  static void memAccess(uc_engine* uc, uc_mem_type type, uint64_t address, int size, int64_t, void* user);
  static bool badMemory(uc_engine* uc, uc_mem_type type, uint64_t address, int size, int64_t value, void* user);
  static void interrupt(uc_engine* uc, uint32_t intno, void* user);
  static bool invalidInsn(uc_engine*, void* user);
  static Slot* slotFor(Machine* m, uint64_t offset);
  static uint64_t mmioRead(uc_engine* uc, uint64_t offset, unsigned size, void* user);
  static void mmioWrite(uc_engine* uc, uint64_t offset, unsigned size, uint64_t value, void* user);
};

}  // namespace nxtmap::emu
