// AccessBytes: how many bytes one access of an ARMv4T load or store instruction moves, from its encoding
// (ARM ARM A4, Thumb A7). Unicorn tells the machine the address of an unaligned access, not its size; the
// fault names it ("read of 4 bytes", "write of 2 bytes").
#pragma once

#include <cstdint>

namespace nxtmap::emu {

// Bytes one access of the load `insn` reads: 1, 2 or 4, 0 if it is no load.
unsigned loadBytes(uint32_t insn, bool thumb);
// Bytes one access of the store `insn` writes: 1, 2 or 4, 0 if it is no store.
unsigned storeBytes(uint32_t insn, bool thumb);

}  // namespace nxtmap::emu
