// DirectStores: guest stores to RAM at full speed on Unicorn 2.0.x, and the exact PC of a store that takes
// Unicorn's slow path (an MMIO store). Unicorn 2.0.1 stubs QEMU's dirty-memory tracking so that every RAM
// page always looks clean: every store to RAM leaves the translated code for the slow path (the memory
// map lookup, the check for translated code on the page), even with no memory hook. The executable
// interposes libunicorn's TLB fill (tlb_set_page_with_attrs_arm): a page in the window given here is
// marked dirty at once (tlb_set_dirty_arm, what QEMU itself does after the first store when the page holds
// no translated code), so its stores stay in the translated code. The machine opens the window on RAM at
// kRamBase only for firmware that runs from flash, and closes it for good (flushing the TLB) at the first
// block it sees run from there: stores into translated code must still go the slow way. Pages that are
// read-only (flash, the stack guard) or MMIO keep their slow path: only the clean-page mark is cleared.
// The store helpers are interposed too, to keep the return address into the translated code of the store in
// progress: from it QEMU restores the guest PC (cpu_restore_state_arm), which Unicorn does not do for an
// MMIO callback. That tells exactly which instruction made an MMIO store, which a count of stores in the
// block (a memory hook's) told before.
#pragma once

#include <cstdint>

namespace nxtmap::emu {

// This Unicorn is one whose internals are known (2.0.x) and the fast store path is not switched off
// (NXTMAP_EMU_SLOW_STORES, UnicornFastPath).
bool directStoresAvailable();
// Stores this thread runs from now on to pages of [begin, end) fill the TLB as dirty (empty: none).
void setDirectRamStores(uint32_t begin, uint32_t end);
// While set, the TLB fills of this thread's CPU record its QEMU CPUState in *slot (once); nullptr stops it.
void setCpuSlot(void** slot);
// Drops every TLB entry of `cpu` (after closing the window, so that no page keeps its direct stores).
void flushTlb(void* cpu);
// Inside an MMIO write callback: sets the guest PC of `cpu` to that of the store in progress. false if no
// slow-path store is in progress or its code is not found (the PC is then left as it was).
bool restoreStorePc(void* cpu);

}  // namespace nxtmap::emu
