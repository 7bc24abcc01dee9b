// The SSC's transmit side at register level, from the AT91SAM7S datasheet's SSC chapter: the bit clock
// MCK / (2 x DIV) (DIV 0: off), DATLEN + 1 bits per word, THR and the PDC feeding the shifter back to back
// while TXEN, SR (TXRDY, TXEMPTY, ENDTX, TXBUFE, TXEN), IER/IDR/IMR, CR's TXDIS over TXEN and SWRST.
#include "host/emu/Ssc.hpp"

#include <gtest/gtest.h>

#include <array>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kCr = 0x00, kCmr = 0x04, kTfmr = 0x1C, kThr = 0x24, kSr = 0x40, kIer = 0x44, kIdr = 0x48,
                   kImr = 0x4C;
constexpr uint32_t kTpr = 0x108, kTcr = 0x10C, kTnpr = 0x118, kTncr = 0x11C, kPtcr = 0x120;
constexpr uint32_t kTxen = 1u << 8, kTxdis = 1u << 9, kSwrst = 1u << 15;
constexpr uint32_t kRam = 0x200000;

struct Ram : GuestMemory {
  std::array<uint8_t, 256> bytes{};
  bool readByte(uint32_t a, uint8_t& v) const override {
    if (a < kRam || a >= kRam + bytes.size()) return false;
    v = bytes[a - kRam];
    return true;
  }
  bool writeByte(uint32_t, uint8_t) override { return false; }
};

struct Rig {
  Clock clock;
  Ram ram;
  Ssc ssc{clock, ram};
  uint32_t reg(uint32_t off) {
    uint32_t v = 0;
    EXPECT_TRUE(ssc.read(off, v)) << off;
    return v;
  }
  void set(uint32_t off, uint32_t v) { EXPECT_TRUE(ssc.write(off, v)) << off; }
  void runTo(uint64_t t) {
    clock.now = t;
    ssc.advanceTo(t);
  }
};

TEST(Ssc, WordTimeIsTwoDivTimesTheBitsPerWord) {
  struct Row {
    uint32_t div, datlen;
    uint64_t cycles;
  };
  const Row rows[] = {{1, 7, 16}, {10, 15, 320}, {0xFFF, 0, 2 * 0xFFF}, {0, 15, 0}, {0x1001, 7, 2 * 1 * 8}};
  for (const Row& r : rows) {
    Rig g;
    g.set(kCmr, r.div);
    g.set(kTfmr, r.datlen);
    EXPECT_EQ(g.ssc.wordCycles(), r.cycles) << "DIV " << r.div << " DATLEN " << r.datlen;
  }
}

TEST(Ssc, StatusAfterResetAndAfterCrWrites) {
  struct Row {
    const char* what;
    uint32_t cr;
    uint32_t sr;
  };
  const uint32_t idle = Ssc::kTxrdy | Ssc::kTxempty | Ssc::kEndtx | Ssc::kTxbufe;
  const Row rows[] = {
      {"no write", 0, idle},
      {"TXEN", kTxen, idle | Ssc::kTxenStatus},
      {"TXEN and TXDIS: disabled", kTxen | kTxdis, idle},
      {"SWRST", kSwrst, idle},
  };
  for (const Row& r : rows) {
    Rig g;
    g.set(kCmr, 4);
    g.set(kTfmr, 15);
    if (r.cr) g.set(kCr, r.cr);
    EXPECT_EQ(g.reg(kSr), r.sr) << r.what;
  }
  Rig g;
  g.set(kCmr, 4);
  g.set(kCr, kTxen);
  g.set(kCr, kSwrst);  // resets the configuration and disables
  EXPECT_EQ(g.reg(kCmr), 0u);
  EXPECT_EQ(g.reg(kSr) & Ssc::kTxenStatus, 0u);
}

TEST(Ssc, ThrWordLeavesAtTheBitClockThenTxemptyRises) {
  Rig g;
  g.set(kCmr, 2);     // bit clock MCK/4
  g.set(kTfmr, 7);    // 8 bits: 32 cycles a word
  g.set(kThr, 0x55);  // transmitter off: the word waits in THR
  EXPECT_EQ(g.reg(kSr) & (Ssc::kTxrdy | Ssc::kTxempty), 0u);
  g.set(kCr, kTxen);  // into the shifter at once: THR free, line busy
  EXPECT_EQ(g.reg(kSr) & (Ssc::kTxrdy | Ssc::kTxempty), Ssc::kTxrdy);
  g.set(kThr, 0x66);
  EXPECT_EQ(g.reg(kSr) & Ssc::kTxrdy, 0u);
  g.runTo(31);
  EXPECT_EQ(g.ssc.wordsSent(), 0u);
  g.runTo(32);  // the second word follows without a gap
  EXPECT_EQ(g.ssc.wordsSent(), 1u);
  EXPECT_EQ(g.reg(kSr) & (Ssc::kTxrdy | Ssc::kTxempty), Ssc::kTxrdy);
  g.runTo(64);
  EXPECT_EQ(g.ssc.wordsSent(), 2u);
  EXPECT_EQ(g.reg(kSr) & (Ssc::kTxrdy | Ssc::kTxempty), Ssc::kTxrdy | Ssc::kTxempty);
}

TEST(Ssc, PdcMovesOneUnitPerWordAndEndtxInterruptsAtTheEndOfTheBuffer) {
  Rig g;
  g.set(kCmr, 1);    // MCK/2
  g.set(kTfmr, 15);  // 16 bits = 2 bytes per PDC transfer, 32 cycles a word
  g.set(kTpr, kRam);
  g.set(kTcr, 3);
  g.set(kTnpr, kRam + 0x40);
  g.set(kTncr, 2);
  g.set(kIer, Ssc::kEndtx);
  EXPECT_EQ(g.reg(kImr), Ssc::kEndtx);
  g.set(kCr, kTxen);
  g.set(kPtcr, 0x100);
  EXPECT_EQ(g.reg(kTcr), 2u);  // the first word is in the shifter
  EXPECT_EQ(g.reg(kTpr), kRam + 2);
  EXPECT_FALSE(g.ssc.irqLine());
  g.runTo(64);  // two words out, the third in the shifter: the current buffer ends, the next is chained
  EXPECT_EQ(g.reg(kTpr), kRam + 0x40);
  EXPECT_EQ(g.reg(kTcr), 2u);
  g.runTo(4 * 32);
  EXPECT_EQ(g.reg(kTcr), 0u);
  EXPECT_TRUE(g.ssc.irqLine());  // ENDTX
  EXPECT_EQ(g.reg(kSr) & (Ssc::kEndtx | Ssc::kTxbufe), Ssc::kEndtx | Ssc::kTxbufe);
  g.runTo(5 * 32);
  EXPECT_EQ(g.ssc.wordsSent(), 5u);
  EXPECT_FALSE(g.ssc.dmaFault());
  g.set(kIdr, Ssc::kEndtx);
  EXPECT_FALSE(g.ssc.irqLine());
}

TEST(Ssc, NoBitClockNoWords) {
  Rig g;
  g.set(kTfmr, 7);
  g.set(kCr, kTxen);
  g.set(kThr, 1);
  g.runTo(100000);
  EXPECT_EQ(g.ssc.wordsSent(), 0u);
  EXPECT_EQ(g.reg(kSr) & Ssc::kTxrdy, 0u);
}

TEST(Ssc, APdcPointerOutsideMemoryIsAFault) {
  Rig g;
  g.set(kCmr, 1);
  g.set(kTpr, 0x300000);
  g.set(kTcr, 1);
  g.set(kCr, kTxen);
  g.set(kPtcr, 0x100);
  EXPECT_TRUE(g.ssc.dmaFault());
}

}  // namespace
}  // namespace nxtmap::emu::test
