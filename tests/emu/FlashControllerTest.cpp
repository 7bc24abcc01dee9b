// The embedded flash controller at register level, from the AT91SAM7S datasheet's EFC chapter: the latch
// filled through the flash address space, the commands with key 0x5A, FRDY/LOCKE/PROGE, the busy time,
// lock regions of 64 pages, and what no firmware may do.
#include "host/emu/FlashController.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nxtmap::emu::test {
namespace {

struct Efc {
  Clock clock;
  std::vector<uint8_t> flash = std::vector<uint8_t>(kFlashBytes, 0xFF);
  std::vector<std::pair<uint32_t, uint32_t>> programmed;
  FlashController efc{clock, flash.data(), [this](uint32_t o, uint32_t n) { programmed.emplace_back(o, n); }};
  static constexpr uint32_t kFlashBytes = FlashController::kPages * FlashController::kPageBytes;

  uint32_t fsr() {
    uint32_t v = 0;
    efc.read(0x68, v);
    return v;
  }
  void fcr(uint32_t cmd, uint32_t page, uint32_t key = 0x5A) { efc.write(0x64, key << 24 | page << 8 | cmd); }
  void fillPage(uint32_t page, uint32_t base) {
    for (uint32_t w = 0; w < 64; ++w) efc.latchWrite(page * 256 + 4 * w, base + w, 4);
  }
  void runFor(uint64_t cycles) {
    clock.now += cycles;
    efc.advanceTo(clock.now);
  }
  uint32_t word(uint32_t offset) const {
    return flash[offset] | flash[offset + 1] << 8 | flash[offset + 2] << 16 | uint32_t{flash[offset + 3]} << 24;
  }
};

TEST(FlashController, WritePageProgramsTheLatchAfterTheBusyTime) {
  Efc e;
  EXPECT_EQ(e.fsr() & FlashController::kFrdy, 1u);
  e.fillPage(0x127, 0x11223300);
  EXPECT_EQ(e.word(0x127 * 256), 0xFFFFFFFFu);  // the latch is not the flash
  e.fcr(1, 0x127);
  EXPECT_EQ(e.fsr() & FlashController::kFrdy, 0u);  // busy
  e.runFor(FlashController::kPageCycles - 1);
  EXPECT_EQ(e.fsr() & FlashController::kFrdy, 0u);
  EXPECT_EQ(e.word(0x127 * 256), 0xFFFFFFFFu);
  e.runFor(1);
  EXPECT_EQ(e.fsr() & FlashController::kFrdy, 1u);
  for (uint32_t w = 0; w < 64; ++w) EXPECT_EQ(e.word(0x127 * 256 + 4 * w), 0x11223300u + w);
  EXPECT_EQ(e.word(0x126 * 256), 0xFFFFFFFFu);  // the neighbours untouched
  EXPECT_EQ(e.word(0x128 * 256), 0xFFFFFFFFu);
  ASSERT_EQ(e.programmed.size(), 1u);
  EXPECT_EQ(e.programmed[0], std::make_pair(0x127u * 256, 256u));
  EXPECT_EQ(e.efc.pagesWritten(), 1u);
}

TEST(FlashController, TheLatchWrapsOverTheFlashAndIsAllOnesAfterACommand) {
  Efc e;
  e.efc.latchWrite(0x300 + 8, 0x12345678, 4);  // word 2 of page 3
  e.fcr(1, 3);
  e.runFor(FlashController::kPageCycles);
  EXPECT_EQ(e.word(0x308), 0x12345678u);
  EXPECT_EQ(e.word(0x300), 0xFFFFFFFFu);
  e.efc.latchWrite(0x300 + 4, 0, 4);  // word 1 only: word 2 is erased again (latch re-initialised)
  e.fcr(1, 3);
  e.runFor(FlashController::kPageCycles);
  EXPECT_EQ(e.word(0x304), 0u);
  EXPECT_EQ(e.word(0x308), 0xFFFFFFFFu);
}

TEST(FlashController, WithoutEraseBeforeProgrammingBitsOnlyClear) {
  Efc e;
  e.efc.latchWrite(0, 0xF0F0FFFF, 4);
  e.fcr(1, 0);
  e.runFor(FlashController::kPageCycles);
  e.efc.write(0x60, 1u << 7);  // NEBP
  e.efc.latchWrite(0, 0xFF00FF0F, 4);
  e.fcr(1, 0);
  e.runFor(FlashController::kPageCycles);
  EXPECT_EQ(e.word(0), 0xF000FF0Fu);
}

TEST(FlashController, CommandTable) {
  struct Row {
    uint32_t key, cmd, page;
    uint32_t fsrAfter;  // FSR bits LOCKE | PROGE right after, FRDY masked off
    bool busy;
  };
  const Row rows[] = {
      {0x5A, 0x1, 5, 0, true},                         // WP
      {0x5B, 0x1, 5, FlashController::kProge, false},  // bad key
      {0x00, 0x2, 5, FlashController::kProge, false},  // no key
      {0x5A, 0x5, 5, FlashController::kProge, false},  // no such command
      {0x5A, 0x2, 5, 0, true},                         // SLB
      {0x5A, 0x4, 5, 0, true},                         // CLB
      {0x5A, 0x3, 5, 0, true},                         // WPL
      {0x5A, 0x8, 0, 0, true},                         // EA
      {0x5A, 0xB, 1, 0, true},                         // SGPB GPNVM1
      {0x5A, 0xB, 2, FlashController::kProge, false},  // SGPB: only 2 GPNVM bits
      {0x5A, 0xD, 0, 0, true},                         // CGPB
  };
  for (const Row& r : rows) {
    Efc e;
    e.fcr(r.cmd, r.page, r.key);
    const uint32_t fsr = e.fsr();
    EXPECT_EQ(fsr & (FlashController::kLocke | FlashController::kProge), r.fsrAfter) << r.cmd << " key " << r.key;
    EXPECT_EQ((fsr & FlashController::kFrdy) == 0, r.busy) << r.cmd;
    EXPECT_EQ(e.fsr() & FlashController::kProge, 0u) << "PROGE clears when FSR is read";
  }
}

TEST(FlashController, LockBitsProtectTheirRegionOf64Pages) {
  Efc e;
  e.fcr(2, 70);  // SLB: region 1 (pages 64..127)
  e.runFor(FlashController::kLockCycles);
  EXPECT_EQ(e.fsr() >> 16, 0x2u);
  EXPECT_TRUE(e.efc.locked(1));
  e.fillPage(127, 0);
  e.fcr(1, 127);  // locked: LOCKE, nothing written, not busy
  uint32_t fsr = e.fsr();
  EXPECT_EQ(fsr & FlashController::kLocke, FlashController::kLocke);
  EXPECT_EQ(fsr & FlashController::kFrdy, 1u);
  EXPECT_EQ(e.fsr() & FlashController::kLocke, 0u);  // cleared on read
  e.runFor(FlashController::kPageCycles);
  EXPECT_EQ(e.word(127 * 256), 0xFFFFFFFFu);
  e.fillPage(128, 7);  // region 2 is not locked
  e.fcr(1, 128);
  e.runFor(FlashController::kPageCycles);
  EXPECT_EQ(e.word(128 * 256), 7u);
  e.fcr(8, 0);  // EA with a locked region: LOCKE
  EXPECT_EQ(e.fsr() & FlashController::kLocke, FlashController::kLocke);
  e.fcr(4, 64);  // CLB
  e.runFor(FlashController::kLockCycles);
  EXPECT_FALSE(e.efc.locked(1));
  e.fcr(3, 200);  // WPL: write page 200 and lock region 3
  e.runFor(FlashController::kPageCycles);
  EXPECT_TRUE(e.efc.locked(3));
  e.fcr(8, 0);
  EXPECT_EQ(e.fsr() & FlashController::kLocke, FlashController::kLocke);
  e.fcr(4, 192);
  e.runFor(FlashController::kLockCycles);
  e.fcr(8, 0);  // EA: everything erased after 15 ms
  e.runFor(FlashController::kEraseAllCycles);
  EXPECT_EQ(e.word(128 * 256), 0xFFFFFFFFu);
}

TEST(FlashController, GpnvmAndSecurityBitsShowInFsr) {
  Efc e;
  e.fcr(0xB, 1);
  e.runFor(FlashController::kLockCycles);
  EXPECT_EQ((e.fsr() >> 8) & 3u, 2u);
  e.fcr(0xD, 1);
  e.runFor(FlashController::kLockCycles);
  EXPECT_EQ((e.fsr() >> 8) & 3u, 0u);
  e.fcr(0xF, 0);
  e.runFor(FlashController::kLockCycles);
  EXPECT_EQ(e.fsr() & FlashController::kSecurity, FlashController::kSecurity);
}

TEST(FlashController, FrdyInterruptFollowsItsEnable) {
  Efc e;
  EXPECT_FALSE(e.efc.irqLine());
  e.efc.write(0x60, 1);  // FRDY interrupt enable
  EXPECT_TRUE(e.efc.irqLine());
  e.fcr(1, 0);
  EXPECT_FALSE(e.efc.irqLine());
  e.runFor(FlashController::kPageCycles);
  EXPECT_TRUE(e.efc.irqLine());
}

TEST(FlashController, MisusesAreReported) {
  struct Row {
    const char* what;
    void (*act)(Efc&);
    const char* needle;
  };
  const Row rows[] = {
      {"byte write", [](Efc& e) { e.efc.latchWrite(0x100, 1, 1); }, "1-byte write"},
      {"halfword write", [](Efc& e) { e.efc.latchWrite(0x100, 1, 2); }, "2-byte write"},
      {"two pages", [](Efc& e) { e.efc.latchWrite(0x100, 1, 4), e.efc.latchWrite(0x200, 1, 4); }, "outside the page"},
      {"other page", [](Efc& e) { e.efc.latchWrite(0x100, 1, 4), e.fcr(1, 2); }, "after the latch was filled"},
      {"write while busy", [](Efc& e) { e.fcr(1, 0), e.efc.latchWrite(0, 1, 4); }, "busy"},
      {"command while busy", [](Efc& e) { e.fcr(1, 0), e.fcr(1, 1); }, "busy"},
      {"stray write", [](Efc& e) { e.efc.latchWrite(0x100, 1, 4), e.runFor(FlashController::kStrayCycles); },
       "not followed by a programming command"},
  };
  for (const Row& r : rows) {
    Efc e;
    r.act(e);
    EXPECT_NE(e.efc.misuse().find(r.needle), std::string::npos) << r.what << ": " << e.efc.misuse();
  }
  Efc fine;  // the datasheet's sequence: no misuse
  fine.fillPage(9, 0);
  fine.fcr(1, 9);
  fine.runFor(FlashController::kPageCycles + FlashController::kStrayCycles);
  EXPECT_EQ(fine.efc.misuse(), "");
}

}  // namespace
}  // namespace nxtmap::emu::test
