// FlashController: the embedded flash controller (EFC) of the AT91SAM7S256 behind MC_FMR/FCR/FSR
// (0xFFFFFF60..68): 1024 pages of 256 bytes, 16 lock regions of 64 pages, 2 GPNVM bits, the security bit.
// Programming as the datasheet describes it: 32-bit words written anywhere in the flash address space fill
// the page latch (word (address >> 2) & 63), then MC_FCR = 0x5A << 24 | PAGEN << 8 | FCMD runs a command:
// WP (1) erase (unless FMR.NEBP) and write the latch into page PAGEN, SLB (2) / CLB (4) set / clear the lock
// bit of PAGEN's region, WPL (3) WP then SLB, EA (8) erase all, SGPB (0xB) / CGPB (0xD) GPNVM bit PAGEN,
// SSB (0xF) the security bit. A wrong key or command sets PROGE; a write or erase of a locked region sets
// LOCKE and changes nothing; both clear when FSR is read. FRDY is 0 while a command runs (kPageCycles per
// page write, kEraseAllCycles for EA, kLockCycles for the others); the flash changes when it ends and the
// latch then reads as all ones again.
// What no firmware may do (a misuse, reported once, the machine stops with it): a byte or halfword write
// to flash, a latch write or a command while FRDY is 0, latch words of two pages before one command, a WP
// of another page than the one written, a latch written and no programming command within kStrayCycles.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>
#include <functional>
#include <string>

namespace nxtmap::emu {

class FlashController : public IoDevice {
 public:
  static constexpr uint32_t kPageBytes = 256, kPages = 1024, kPagesPerRegion = 64;
  static constexpr uint64_t kPageCycles = kMckHz * 6 / 1000;       // page erase + write: 6 ms
  static constexpr uint64_t kEraseAllCycles = kMckHz * 15 / 1000;  // full erase: 15 ms
  static constexpr uint64_t kLockCycles = kMckHz * 6 / 1000;       // lock, unlock, GPNVM, security bit
  static constexpr uint64_t kStrayCycles = kMckHz * 10 / 1000;     // latch written, no command: 10 ms
  static constexpr uint32_t kFrdy = 1, kLocke = 1u << 2, kProge = 1u << 3, kSecurity = 1u << 4;

  // flash: the kPages * kPageBytes bytes the CPU reads; onProgrammed(offset, bytes) after they changed.
  FlashController(Clock& clock, uint8_t* flash, std::function<void(uint32_t, uint32_t)> onProgrammed);

  const char* name() const override { return "EFC"; }
  // offset from the MC base: 0x60 FMR, 0x64 FCR, 0x68 FSR.
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  uint64_t nextEventAt() const override;
  void advanceTo(uint64_t now) override;

  // A CPU store of `size` bytes at flash offset `offset` (0..256 KiB): fills the latch.
  void latchWrite(uint32_t offset, uint32_t value, int size);
  bool busy() const { return busyUntil_ != kNever; }
  // The SYS interrupt share: FRDY, LOCKE or PROGE with its enable in FMR (bits 0, 2, 3).
  bool irqLine() const { return ((fmr_ & kFrdy) && !busy()) || (fmr_ & fsr_ & (kLocke | kProge)) != 0; }
  // The first misuse seen (empty: none), and the flash offset it concerns.
  const std::string& misuse() const { return misuse_; }
  uint32_t misuseOffset() const { return misuseOffset_; }
  bool locked(uint32_t region) const { return (locks_ >> region) & 1u; }
  uint64_t pagesWritten() const { return pagesWritten_; }

 private:
  void command(uint32_t value);
  void finish();
  void misused(std::string what, uint32_t offset);

  Clock& clock_;
  uint8_t* flash_;
  std::function<void(uint32_t, uint32_t)> onProgrammed_;
  std::array<uint32_t, kPageBytes / 4> latch_{};
  uint32_t fmr_ = 0, fsr_ = 0, locks_ = 0, gpnvm_ = 0;
  bool security_ = false;
  int latchPage_ = -1;           // page of the words latched since the last command, -1 none
  uint64_t latchedAt_ = kNever;  // first latch write since the last command
  uint64_t busyUntil_ = kNever;
  uint32_t pending_ = 0;  // the command that runs until busyUntil_
  uint64_t pagesWritten_ = 0;
  std::string misuse_;
  uint32_t misuseOffset_ = 0;
};

}  // namespace nxtmap::emu
