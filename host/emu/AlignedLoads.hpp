// AlignedLoads: unaligned loads caught by Unicorn's own translated code instead of a hook on every memory
// access (a hook on loads makes every load take Unicorn's slow path). The executable interposes two
// functions of libunicorn 2.0.x (QEMU 5.0 inside): the one that emits a guest load, to ask for an alignment
// check on loads of 2 and 4 bytes (MO_ALIGN), and the one QEMU calls when that check fails, to learn the
// address; the failed check ends as a data abort (UC_HOOK_INTR 4) at the load, before it runs. SCTLR.A is
// no help: QEMU 5.0 ignores it for ARMv4T. Stores stay checked by the machine's store hook.
#pragma once

#include <cstdint>
#include <optional>

namespace nxtmap::emu {

// Whether machines made from now on have Unicorn check load alignment: this Unicorn can (2.0.x only: its
// MemOp encoding is known) and it is not switched off. Off, a machine hooks every load instead (slower, the
// same faults); NXTMAP_EMU_LOAD_HOOK switches it off for a process.
bool alignedLoadsAvailable();
void setAlignedLoadsAllowed(bool on);
// Loads this thread translates from now on check alignment (on only where available). Each machine sets
// it before it starts the CPU (on only if alignedLoadsAvailable() said so when it was made); translated code
// keeps what it was translated with (each machine its own).
void setAlignedLoads(bool on);
// The address of the unaligned load this thread's CPU last stopped at, once (then forgotten).
std::optional<uint32_t> takeUnalignedLoad();
// Bytes one access of the ARMv4T load `insn` reads: 1, 2 or 4, 0 if it is no load (ARM ARM A4, Thumb A7).
unsigned loadBytes(uint32_t insn, bool thumb);

}  // namespace nxtmap::emu
