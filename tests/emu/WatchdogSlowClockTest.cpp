// The watchdog counts the slow clock, an RC oscillator of 22..42 kHz (not an exact 32.768 kHz crystal):
// each emulated brick draws its slow clock from that range with its seed, and the watchdog's period
// follows it, so a restart cadence that holds only at 32.768 kHz fails on a fast part.
#include "host/emu/Watchdog.hpp"

#include <gtest/gtest.h>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kWdcr = 0x0, kWdmr = 0x4;
constexpr uint32_t kRestart = 0xA5000001u;
// WDV = 64 (as our firmware), WDD = 0xFFF, reset enabled.
constexpr uint32_t kMode64 = 64u | (0xFFFu << 16) | (1u << 13);

TEST(SlowClock, SeedsDrawFromTheRcRangeAndSpreadOverIt) {
  uint32_t lo = kSlowClockMaxHz, hi = kSlowClockMinHz;
  for (uint64_t seed = 0; seed < 1000; ++seed) {
    const uint32_t hz = slowClockHzForSeed(seed);
    ASSERT_GE(hz, kSlowClockMinHz);
    ASSERT_LE(hz, kSlowClockMaxHz);
    lo = std::min(lo, hz);
    hi = std::max(hi, hz);
  }
  EXPECT_LT(lo, 23000u);
  EXPECT_GT(hi, 41000u);
  EXPECT_EQ(slowClockHzForSeed(7), slowClockHzForSeed(7));  // same seed, same brick
}

struct PeriodRow {
  uint32_t slowHz;
  double periodMs;  // (64 + 1) x 128 / SLCK
};

TEST(SlowClock, TheWatchdogPeriodFollowsTheSlowClock) {
  const PeriodRow rows[] = {{22000, 378.2}, {32768, 253.9}, {42000, 198.1}};
  for (const PeriodRow& r : rows) {
    SCOPED_TRACE(r.slowHz);
    Clock clock;
    clock.slowClockHz = r.slowHz;
    Watchdog wdt(clock);
    wdt.write(kWdmr, kMode64);
    EXPECT_NEAR(secondsFromCycles(wdt.nextEventAt()) * 1000.0, r.periodMs, 0.2);
  }
}

struct CadenceRow {
  uint32_t slowHz;
  uint32_t restartEveryMs;
  bool expires;
};

// Restarts every 220 ms hold at 32.768 kHz (254 ms) but not on a 42 kHz part (198 ms); our firmware's
// worst gap (a few ms at boot, then 1 ms) holds everywhere.
TEST(SlowClock, ARestartCadenceThatHoldsOnlyAtTheNominalClockExpires) {
  const CadenceRow rows[] = {
      {32768, 220, false}, {42000, 220, true}, {22000, 220, false}, {42000, 5, false}, {42000, 190, false}};
  for (const CadenceRow& r : rows) {
    SCOPED_TRACE(testing::Message() << r.slowHz << " Hz, every " << r.restartEveryMs << " ms");
    Clock clock;
    clock.slowClockHz = r.slowHz;
    Watchdog wdt(clock);
    wdt.write(kWdmr, kMode64);
    for (int i = 0; i < 20 && !wdt.expired(); ++i) {
      clock.now += cyclesFromMs(r.restartEveryMs);
      wdt.advanceTo(clock.now);
      if (!wdt.expired()) wdt.write(kWdcr, kRestart);
    }
    EXPECT_EQ(wdt.expired(), r.expires);
    if (!r.expires) {
      EXPECT_EQ(wdt.longestGapCycles(), cyclesFromMs(r.restartEveryMs));
    }
  }
}

}  // namespace
}  // namespace nxtmap::emu::test
