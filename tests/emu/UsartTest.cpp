// The USART's baud rate generator at register level (AT91SAM7S datasheet, USART "Baud Rate Generator",
// asynchronous mode): baud = MCK / (8 (2 - OVER) (CD + FP / 8)), CD = 0 stops it; a byte (start, 8 data,
// stop) lasts 10 bits. The fractional part FP (BRGR bits 16-18) is what LEGO's d_bt.r and d_hispeed.r
// compute; without it a firmware's fractional rate would run at the integer one.
#include "host/emu/Usart.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kCr = 0x00, kMr = 0x04, kThr = 0x1C, kBrgr = 0x20;
constexpr uint32_t kTxen = 1u << 6, kOver = 1u << 19;

struct NoMemory : GuestMemory {
  bool readByte(uint32_t, uint8_t&) const override { return false; }
  bool writeByte(uint32_t, uint8_t) override { return false; }
};

struct Listener : SerialPeer {
  std::vector<uint64_t> at;  // when each byte arrived (cycles)
  Clock* clock = nullptr;
  void fromArm(uint8_t) override { at.push_back(clock->now); }
  bool hasByteForArm() const override { return false; }
  uint8_t takeByteForArm() override { return 0; }
};

struct Rig {
  Clock clock;
  NoMemory mem;
  Listener peer;
  Usart us{clock, mem, peer};
  Rig() { peer.clock = &clock; }
  // Cycles from a THR write to the byte's end, the line otherwise idle.
  uint64_t byteCycles(uint32_t mr, uint32_t brgr) {
    us.write(kMr, mr);
    us.write(kBrgr, brgr);
    us.write(kCr, kTxen);
    clock.now = 1000;
    us.write(kThr, 0x55);
    const uint64_t end = us.nextEventAt();
    if (end == kNever) return 0;
    clock.now = end;
    us.advanceTo(end);
    EXPECT_EQ(peer.at.size(), 1u);
    return end - 1000;
  }
};

TEST(Usart, BaudRateFromCdFpAndOver) {
  struct Row {
    const char* what;
    uint32_t mr, brgr;
    uint64_t byteCycles;  // 10 bits
  };
  const Row rows[] = {
      {"OVER 0, CD 26: 16 x 26 cycles a bit", 0, 26, 10 * 16 * 26},
      {"OVER 1, CD 13 (our BlueCore: 462 kbaud)", kOver, 13, 10 * 8 * 13},
      {"OVER 1, CD 13, FP 3: 13.375", kOver, 13 | 3u << 16, 10 * (8 * 13 + 3)},
      {"OVER 0, CD 13, FP 7: 13.875", 0, 13 | 7u << 16, 10 * 2 * (8 * 13 + 7)},
      {"LEGO d_hispeed at 921.6 kbaud: CD 6, FP 4", kOver, 6 | 4u << 16, 10 * (8 * 6 + 4)},
      {"bits above FP are not kept", kOver, 13 | 0xF8u << 16, 10 * 8 * 13},
      {"CD 0: no clock, nothing sent", kOver, 0 | 5u << 16, 0},
  };
  for (const Row& r : rows) {
    Rig g;
    EXPECT_EQ(g.byteCycles(r.mr, r.brgr), r.byteCycles) << r.what;
  }
}

TEST(Usart, BrgrReadsBackCdAndFp) {
  Rig g;
  g.us.write(kBrgr, 0xFFFFFFFF);
  uint32_t v = 0;
  ASSERT_TRUE(g.us.read(kBrgr, v));
  EXPECT_EQ(v, 0x7FFFFu);
}

TEST(Usart, FractionalRateMatchesTheDatasheetFormulaToTheCycle) {
  // LEGO's formula for 460.8 kbaud gives CD = 13, FP = 0 at MCK = 48.05 MHz; at 38400 baud it needs FP.
  const uint32_t osc8 = static_cast<uint32_t>(kMckHz / 8), baud = 38400;
  const uint32_t cd = osc8 / baud, fp = (osc8 - cd * baud) / ((baud + 4) / 8);
  EXPECT_EQ(cd, 156u);
  EXPECT_EQ(fp, 3u);
  Rig g;
  const uint64_t cycles = g.byteCycles(kOver, cd | fp << 16);  // OVER 1: 8 x oversampling, as LEGO sets it
  const double baudSeen = 10.0 * static_cast<double>(kMckHz) / static_cast<double>(cycles);
  EXPECT_NEAR(baudSeen, 38400.0, 38400.0 * 0.001);  // within 0.1 %; CD alone would be 0.27 % fast
}

}  // namespace
}  // namespace nxtmap::emu::test
