// AlignedAccess: unaligned loads and stores caught by Unicorn's own translated code instead of a hook on
// every memory access (any memory hook makes every load and store of Unicorn 2.0.1 take its slow path). The
// executable interposes three functions of libunicorn 2.0.x (QEMU 5.0 inside): the two that emit a guest
// load and a guest store, to ask for an alignment check on accesses of 2 and 4 bytes (MO_ALIGN), and the one
// QEMU calls when that check fails, to learn the address and whether a load or a store failed; the failed
// check ends as a data abort (UC_HOOK_INTR 4) at the instruction, before it reads or writes anything. SCTLR.A
// is no help: QEMU 5.0 ignores it for ARMv4T.
#pragma once

#include <cstdint>
#include <optional>

namespace nxtmap::emu {

// Whether machines made from now on have Unicorn check alignment: this Unicorn can (2.0.x only: its MemOp
// encoding is known) and it is not switched off. Off, a machine hooks every load and store instead (slower,
// the same faults); NXTMAP_EMU_LOAD_HOOK switches it off for a process.
bool alignedAccessAvailable();
void setAlignedAccessAllowed(bool on);
// Loads and stores this thread translates from now on check alignment (on only where available). Each
// machine sets it before it starts the CPU (on only if alignedAccessAvailable() said so when it was made);
// translated code keeps what it was translated with (each machine its own).
void setAlignedAccess(bool on);

struct UnalignedAccess {
  uint32_t address = 0;
  bool store = false;
};
// The unaligned access this thread's CPU last stopped at, once (then forgotten).
std::optional<UnalignedAccess> takeUnalignedAccess();

}  // namespace nxtmap::emu
