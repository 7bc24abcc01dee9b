// StoreSite: which instruction of a translated block made a given store, found by decoding the block and
// computing each single-register store's effective address from the registers as they are at that store
// (Unicorn hands a memory hook neither the PC nor the instruction). ARMv4T only: ARM STR/STRB (immediate or
// shifted register, pre/post-indexed, writeback) and STRH; Thumb STR/STRB/STRH (immediate, register,
// SP-relative). Multiple stores (STM, PUSH) and SWP are never a site: the machine then falls back to
// delivering at the block's end.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>
#include <cstdint>
#include <optional>

namespace nxtmap::emu {

struct StoreSite {
  uint32_t pc = 0;         // address of the store instruction
  uint32_t next = 0;       // address of the instruction after it
  int base = -1;           // register written back after the store (ARM P=0 or W=1), -1 none
  uint32_t baseValue = 0;  // its value after the writeback
};

// The one store instruction in [blockStart, blockStart + blockBytes) that writes `value` (`bytes` 1, 2 or 4)
// at `address` with the registers `regs` (r0..r15; r15 ignored); nothing if none or more than one match.
// `writeOrdinal` (1-based count of memory writes made in the block so far, 0 unknown) tells apart stores that
// look alike (the same `str r1, [r2]` twice with r1, r2 reloaded between them).
std::optional<StoreSite> findStoreSite(const GuestMemory& memory, uint32_t blockStart, uint32_t blockBytes, bool thumb,
                                       const std::array<uint32_t, 16>& regs, uint32_t address, unsigned bytes,
                                       uint32_t value, unsigned writeOrdinal = 0);

}  // namespace nxtmap::emu
