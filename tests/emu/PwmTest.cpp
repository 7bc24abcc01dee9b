// The PWM controller at register level, from the AT91SAM7S datasheet's PWM chapter: the channel clock
// (CPRE: MCK / 2^CPRE, or clock A / B from MR's DIVx and PREx, off when DIVx = 0), the period (CPRD ticks,
// doubled when centre aligned), ENA/DIS/SR, the period interrupt (ISR bit at each period end, cleared by
// reading ISR; IER/IDR/IMR), CCNT, and CUPD taking effect at the next period end (CPD: 0 duty, 1 period).
#include "host/emu/Pwm.hpp"

#include <gtest/gtest.h>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kMr = 0x00, kEna = 0x04, kDis = 0x08, kSr = 0x0C, kIer = 0x10, kIdr = 0x14, kImr = 0x18, kIsr = 0x1C;
constexpr uint32_t cmr(int n) { return 0x200 + 0x20 * static_cast<uint32_t>(n); }
constexpr uint32_t cdty(int n) { return cmr(n) + 4; }
constexpr uint32_t cprd(int n) { return cmr(n) + 8; }
constexpr uint32_t ccnt(int n) { return cmr(n) + 0xC; }
constexpr uint32_t cupd(int n) { return cmr(n) + 0x10; }

struct Rig {
  Clock clock;
  Pwm pwm{clock};
  uint32_t reg(uint32_t off) {
    uint32_t v = 0;
    EXPECT_TRUE(pwm.read(off, v)) << off;
    return v;
  }
  void set(uint32_t off, uint32_t v) { EXPECT_TRUE(pwm.write(off, v)) << off; }
  void runTo(uint64_t t) {
    clock.now = t;
    pwm.advanceTo(t);
  }
};

struct PeriodRow {
  const char* what;
  uint32_t mr, cmr, cprd;
  uint64_t cycles;  // MCK cycles per period
};

TEST(Pwm, PeriodFromTheChannelClockAndCprd) {
  const PeriodRow rows[] = {
      {"MCK, CPRD 100", 0, 0x0, 100, 100},
      {"MCK/8", 0, 0x3, 100, 800},
      {"MCK/1024", 0, 0xA, 3, 3072},
      {"centre aligned doubles", 0, 0x3 | 1u << 8, 100, 1600},
      {"clock A = MCK / 2^PREA / DIVA", 0x0305, 0xB, 10, 8 * 5 * 10},
      {"clock B from the upper half", 0x0A070000, 0xC, 10, 1024 * 7 * 10},
      {"clock A off (DIVA 0)", 0x0300, 0xB, 10, 0},
      {"clock B off while A runs", 0x0305, 0xC, 10, 0},
      {"CPRE 13..15 reserved: off", 0, 0xD, 10, 0},
      {"CPRD 0: no period", 0, 0x0, 0, 0},
  };
  for (const PeriodRow& r : rows) {
    Rig g;
    g.set(kMr, r.mr);
    g.set(cmr(2), r.cmr);
    g.set(cprd(2), r.cprd);
    EXPECT_EQ(g.pwm.periodCycles(2), r.cycles) << r.what;
    EXPECT_EQ(g.reg(cmr(2)), r.cmr) << r.what;
  }
}

TEST(Pwm, EnableDisableAndInterruptMaskRegisters) {
  struct Row {
    const char* what;
    uint32_t off, value, readOff, expect;
  };
  const Row rows[] = {
      {"ENA sets SR", kEna, 0x5, kSr, 0x5},
      {"ENA ignores bits above channel 3", kEna, 0xF0, kSr, 0x0},
      {"IER sets IMR", kIer, 0x3, kImr, 0x3},
      {"IER ignores bits above channel 3", kIer, 0x30, kImr, 0x0},
      {"MR keeps DIVA/PREA/DIVB/PREB", kMr, 0xFFFFFFFF, kMr, 0x0FFF0FFF},
  };
  for (const Row& r : rows) {
    Rig g;
    g.set(r.off, r.value);
    EXPECT_EQ(g.reg(r.readOff), r.expect) << r.what;
  }
  Rig g;
  g.set(kEna, 0xF);
  g.set(kDis, 0x6);
  EXPECT_EQ(g.reg(kSr), 0x9u);
  g.set(kIer, 0xF);
  g.set(kIdr, 0x5);
  EXPECT_EQ(g.reg(kImr), 0xAu);
}

TEST(Pwm, PeriodEndSetsIsrReadClearsItAndRaisesTheLineWhenEnabled) {
  Rig g;
  g.set(cmr(1), 0x3);  // MCK/8
  g.set(cprd(1), 50);  // 400 cycles
  g.set(kEna, 1u << 1);
  EXPECT_EQ(g.pwm.nextEventAt(), kNever);  // interrupt not enabled: nothing to plan
  g.set(kIer, 1u << 1);
  EXPECT_EQ(g.pwm.nextEventAt(), 400u);
  g.runTo(399);
  EXPECT_FALSE(g.pwm.irqLine());
  g.runTo(400);
  EXPECT_TRUE(g.pwm.irqLine());
  EXPECT_EQ(g.reg(kIsr), 1u << 1);
  EXPECT_FALSE(g.pwm.irqLine());
  EXPECT_EQ(g.reg(kIsr), 0u);  // cleared by the read
  EXPECT_EQ(g.pwm.nextEventAt(), 800u);
  g.runTo(1000);  // 200 cycles into the third period
  EXPECT_EQ(g.reg(ccnt(1)), 200u / 8);
  g.set(kIdr, 1u << 1);
  EXPECT_EQ(g.reg(kIsr), 1u << 1);  // ISR is set whatever IMR says
  EXPECT_FALSE(g.pwm.irqLine());
}

TEST(Pwm, CounterOfADisabledChannelReadsZero) {
  Rig g;
  g.set(cmr(0), 0);
  g.set(cprd(0), 1000);
  g.runTo(500);
  EXPECT_EQ(g.reg(ccnt(0)), 0u);
  g.set(kEna, 1);
  g.runTo(800);
  EXPECT_EQ(g.reg(ccnt(0)), 300u);  // counts from the enable
}

TEST(Pwm, CupdTakesEffectAtTheNextPeriodEnd) {
  struct Row {
    const char* what;
    uint32_t cmrBits;
    uint32_t dutyAfter, periodAfter;
  };
  const Row rows[] = {
      {"CPD 0: the duty", 0, 7, 100},
      {"CPD 1: the period", 1u << 10, 20, 7},
  };
  for (const Row& r : rows) {
    Rig g;
    g.set(cmr(3), r.cmrBits);
    g.set(cdty(3), 20);
    g.set(cprd(3), 100);
    g.set(kEna, 1u << 3);
    g.runTo(50);
    g.set(cupd(3), 7);
    EXPECT_EQ(g.reg(cdty(3)), 20u) << r.what;  // not before the period ends
    EXPECT_EQ(g.reg(cprd(3)), 100u) << r.what;
    g.runTo(100);
    EXPECT_EQ(g.reg(cdty(3)), r.dutyAfter) << r.what;
    EXPECT_EQ(g.reg(cprd(3)), r.periodAfter) << r.what;
  }
}

TEST(Pwm, UnmodelledRegistersAreRefused) {
  Rig g;
  uint32_t v = 0;
  EXPECT_FALSE(g.pwm.read(0x300 - 4, v));
  EXPECT_FALSE(g.pwm.write(ccnt(0), 1));  // CCNT is read-only
  EXPECT_FALSE(g.pwm.read(cupd(0), v));   // CUPD is write-only
}

}  // namespace
}  // namespace nxtmap::emu::test
