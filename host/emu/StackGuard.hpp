// StackGuard: a store in [low, limit) (between the end of .bss and the lowest stack) is a stack overflow,
// caught without a memory hook (any memory hook makes every load and store of Unicorn 2.0.1 take its slow
// path). RAM at kRamBase is mapped in pieces over the one RAM buffer: the target pages (1 KiB on the
// ARMv4T) wholly inside the guard read-only, so a store there ends in the machine's write-protect hook
// before it writes (the PC is then that of the store's block, as a memory hook saw it); the rest plain RAM.
// The guard's ends rarely fall on page edges: the bytes of the guard on the page it shares with .bss and on
// the page it shares with the stacks (for our firmware 136 and 320 bytes; all 88 bytes of the RAM-run
// image's guard) stay plain RAM, painted (RAM is painted before the run) and checked when the CPU stops
// 1 ms of emulated time after the last check, and when a run returns: a word there that lost its paint is
// the overflow, at its address, but found after the store (the PC is where the CPU stopped; a byte store
// is named by its word) and blind to a store of the paint itself. Those pages hold the hottest stack and
// .bss bytes: watching them instead (MMIO callbacks) cost more than the hook on every store. A store
// through the RAM alias at address 0 after the remap passes the read-only pages (the hook did not see it
// either).
#pragma once

#include <cstdint>
#include <optional>

struct uc_struct;

namespace nxtmap::emu {

class StackGuard {
 public:
  // [low, limit) clamped to RAM; empty when limit <= low.
  StackGuard(uint32_t low, uint32_t limit);
  bool empty() const { return limit_ <= low_; }
  bool contains(uint32_t address) const { return address >= low_ && address < limit_; }
  uint32_t low() const { return low_; }
  uint32_t limit() const { return limit_; }

  // Maps RAM [kRamBase, kRamBase + kRamSize) onto `ram` as above; all of it plain RAM, with nothing to check
  // after, when the guard is empty or `pages` is false (a memory hook checks every store then).
  void mapRam(uc_struct* uc, uint8_t* ram, bool pages);
  // The address of the word holding a guard byte on a shared page that lost the paint `paint` since the RAM
  // was painted (the one nearest the stacks, then the one nearest .bss), if any.
  std::optional<uint32_t> paintLost(uint8_t paint) const;

 private:
  bool intact(uint32_t begin, uint32_t end, uint8_t paint) const;

  uint32_t low_ = 0, limit_ = 0;
  const uint8_t* ram_ = nullptr;
  // The painted ranges checked after the fact: [lowStrip, lowStripEnd) and [highStrip, limit_).
  uint32_t lowStrip_ = 0, lowStripEnd_ = 0, highStrip_ = 0;
};

}  // namespace nxtmap::emu
