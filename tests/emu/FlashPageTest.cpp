// The brick's flash driver (firmware/board/FlashPage.hpp) programming the emulator's flash controller
// (FlashController, the model LEGO's own firmware formats its file system through): a page is written whole
// and reads back, its neighbours stay as they were, a locked region is unlocked first, and a page the
// controller refuses or that reads back otherwise is reported, not taken as kept.
#include "firmware/board/FlashPage.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "host/emu/FlashController.hpp"

namespace nxtmap::emu::test {
namespace {

// The chip as FlashPage sees it: MC_FSR / MC_FCR of the controller, the flash behind its address space.
struct Chip {
  static constexpr uint32_t kBytes = FlashController::kPages * FlashController::kPageBytes;
  Clock clock;
  std::vector<uint8_t> flash = std::vector<uint8_t>(kBytes, 0xFF);
  FlashController efc{clock, flash.data(), [](uint32_t, uint32_t) {}};
  bool spoil = false;  // the next page programmed reads back with one bit wrong (a worn page)
  int commands = 0;

  uint32_t read(uint32_t addr) {
    uint32_t v = 0;
    if (addr == fw::reg::kMcFsr) efc.read(0x68, v);
    if (addr >= fw::reg::kFlashBase && addr < fw::reg::kFlashBase + kBytes) {
      const uint32_t o = addr - fw::reg::kFlashBase;
      v = flash[o] | flash[o + 1] << 8 | flash[o + 2] << 16 | uint32_t{flash[o + 3]} << 24;
    }
    return v;
  }
  void write(uint32_t addr, uint32_t value) {
    ASSERT_TRUE(addr >= fw::reg::kFlashBase && addr < fw::reg::kFlashBase + kBytes) << std::hex << addr;
    efc.latchWrite(addr - fw::reg::kFlashBase, value, 4);
  }
  uint32_t address(const void*) { return 0; }

  // FlashPage::Command: the command runs to its end (the brick polls FRDY from RAM meanwhile).
  static uint32_t command(uint32_t fcr) {
    Chip& c = *current;
    ++c.commands;
    c.efc.write(0x64, fcr);
    uint32_t seen = 0, fsr = 0;
    do {
      c.clock.now += 1000;
      c.efc.advanceTo(c.clock.now);
      c.efc.read(0x68, fsr);
      seen |= fsr;
    } while ((fsr & FlashController::kFrdy) == 0);
    if (c.spoil && (fcr & 0xF) == 1) c.flash[(fcr >> 8 & 0x3FF) * 256] ^= 1;
    c.spoil = false;
    return seen;
  }
  static Chip* current;
};
Chip* Chip::current = nullptr;

struct Rig {
  Chip chip;
  fw::FlashPage<Chip> page{chip, &Chip::command};
  Rig() { Chip::current = &chip; }
};

const std::vector<uint32_t> kWords = {0x6857584E, 0xFFFF7D2A, 17800, 1, 4000000, 0, 250000, 0, 0x12345678};

TEST(FlashPage, APageIsWrittenWholeAndReadsBack) {
  Rig r;
  ASSERT_TRUE(r.page.write(1023, kWords.data(), static_cast<uint32_t>(kWords.size())));
  for (uint32_t i = 0; i < kWords.size(); ++i) EXPECT_EQ(r.page.read(1023, i), kWords[i]) << i;
  for (uint32_t i = static_cast<uint32_t>(kWords.size()); i < 64; ++i) EXPECT_EQ(r.page.read(1023, i), ~0u) << i;
  EXPECT_EQ(r.page.read(1022, 63), ~0u) << "the page before is untouched";
  EXPECT_EQ(r.chip.efc.pagesWritten(), 1u);
  EXPECT_EQ(r.chip.efc.misuse(), "");
  // Written again with other words: the old ones are erased, not ANDed in.
  const std::vector<uint32_t> other = {0, 0xFFFFFFFF, 0xA5A5A5A5};
  ASSERT_TRUE(r.page.write(1023, other.data(), 3));
  for (uint32_t i = 0; i < 3; ++i) EXPECT_EQ(r.page.read(1023, i), other[i]) << i;
  EXPECT_EQ(r.page.read(1023, 4), ~0u);
  EXPECT_EQ(r.chip.efc.misuse(), "");
}

TEST(FlashPage, ALockedRegionIsUnlockedFirst) {
  Rig r;
  r.chip.efc.write(0x64, 0x5Au << 24 | 1000u << 8 | 2u);  // SLB: region 15 (pages 960..1023)
  r.chip.clock.now += FlashController::kLockCycles;
  r.chip.efc.advanceTo(r.chip.clock.now);
  ASSERT_TRUE(r.chip.efc.locked(15));
  ASSERT_TRUE(r.page.write(1023, kWords.data(), static_cast<uint32_t>(kWords.size())));
  EXPECT_FALSE(r.chip.efc.locked(15));
  EXPECT_EQ(r.chip.commands, 2);  // unlock, write
  EXPECT_EQ(r.page.read(1023, 0), kWords[0]);
  EXPECT_EQ(r.chip.efc.misuse(), "");
}

TEST(FlashPage, WhatCannotBeWrittenIsReportedNotTakenAsKept) {
  Rig r;
  EXPECT_FALSE(r.page.write(1024, kWords.data(), 1)) << "no page 1024";
  std::vector<uint32_t> tooMany(65, 0);
  EXPECT_FALSE(r.page.write(1023, tooMany.data(), 65)) << "more than a page";
  EXPECT_EQ(r.chip.commands, 0) << "nothing was tried";
  r.chip.spoil = true;
  EXPECT_FALSE(r.page.write(1023, kWords.data(), static_cast<uint32_t>(kWords.size()))) << "read back wrong";
  EXPECT_EQ(r.chip.efc.misuse(), "");
}

}  // namespace
}  // namespace nxtmap::emu::test
