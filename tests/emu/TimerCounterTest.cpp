// The timer/counter at register level (AT91SAM7S datasheet, TC chapter): the clock selection, the RC
// compare with and without the RC trigger, the counter's overflow, and capture mode as LEGO's tachometers
// use it (d_output.r: MCK/1024, ABETRG, ETRGEDG both edges, LDRA rising, ETRGS interrupt, MTIOA read in
// the handler): RA/RB loads on TIOA edges, the external trigger restarting the count, LOVRS, LDBSTOP.
#include "host/emu/TimerCounter.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kCcr = 0x00, kCmr = 0x04, kCv = 0x10, kRa = 0x14, kRb = 0x18, kRc = 0x1C, kSr = 0x20, kIer = 0x24,
                   kIdr = 0x28, kImr = 0x2C;
constexpr uint32_t kClken = 1, kClkdis = 2, kSwtrg = 4;
constexpr uint32_t kDiv1024 = 4, kCpctrg = 1u << 14, kWave = 1u << 15, kAbetrg = 1u << 10;
constexpr uint32_t etrgedg(uint32_t e) { return e << 8; }
constexpr uint32_t ldra(uint32_t e) { return e << 16; }
constexpr uint32_t ldrb(uint32_t e) { return e << 18; }
constexpr uint32_t kRising = 1, kFalling = 2, kBoth = 3;
constexpr uint32_t kLegoTacho = kDiv1024 | kAbetrg | etrgedg(kBoth) | ldra(kRising);

struct Rig {
  Clock clock;
  TimerCounter tc{clock};
  int ch = 1;
  uint32_t reg(uint32_t off) {
    uint32_t v = 0;
    EXPECT_TRUE(tc.read(0x40 * static_cast<uint32_t>(ch) + off, v)) << off;
    return v;
  }
  void set(uint32_t off, uint32_t v) { EXPECT_TRUE(tc.write(0x40 * static_cast<uint32_t>(ch) + off, v)) << off; }
  void at(uint64_t t) { clock.now = t; }
};

TEST(TimerCounterModel, CounterFromTheSelectedClock) {
  struct Row {
    uint32_t tcclks;
    uint64_t cycles;
    uint32_t cv;
  };
  const Row rows[] = {{0, 1000, 500}, {1, 1000, 125}, {2, 1000, 31},
                      {3, 1000, 7},   {4, 10240, 10}, {4, 1024ull * 70000, 70000 & 0xFFFF},
                      {5, 100000, 0} /* XC0: not modelled, stands */};
  for (const Row& r : rows) {
    Rig g;
    g.set(kCmr, r.tcclks);
    g.set(kCcr, kClken);
    g.at(r.cycles);
    EXPECT_EQ(g.reg(kCv), r.cv) << "TCCLKS " << r.tcclks;
  }
}

TEST(TimerCounterModel, RcCompareWithTheTriggerRestartsTheCountAndInterrupts) {
  Rig g;
  g.set(kCmr, 0 | kCpctrg);  // MCK/2
  g.set(kRc, 100);
  g.set(kIer, TimerCounter::kCpcs);
  g.set(kCcr, kClken | kSwtrg);
  EXPECT_EQ(g.tc.nextEventAt(), 200u);
  g.at(199);
  EXPECT_FALSE(g.tc.irqLine(1));
  g.at(200);
  EXPECT_TRUE(g.tc.irqLine(1));
  EXPECT_EQ(g.reg(kCv), 0u);
  EXPECT_EQ(g.reg(kSr) & 0xFF, TimerCounter::kCpcs);
  EXPECT_FALSE(g.tc.irqLine(1));  // the SR read cleared it
  EXPECT_EQ(g.tc.nextEventAt(), 400u);
  g.set(kIdr, TimerCounter::kCpcs);
  EXPECT_EQ(g.reg(kImr), 0u);
  EXPECT_EQ(g.tc.nextEventAt(), kNever);
}

TEST(TimerCounterModel, FreeRunningCounterOverflowSetsCovfs) {
  Rig g;
  g.set(kCmr, 0);
  g.set(kIer, TimerCounter::kCovfs);
  g.set(kCcr, kClken);
  EXPECT_EQ(g.tc.nextEventAt(), 2u * 65536);
  g.at(2 * 65536 - 1);
  EXPECT_EQ(g.reg(kSr) & TimerCounter::kCovfs, 0u);
  g.at(2 * 65536);
  EXPECT_TRUE(g.tc.irqLine(1));
  EXPECT_EQ(g.reg(kSr) & TimerCounter::kCovfs, TimerCounter::kCovfs);
  EXPECT_EQ(g.reg(kSr) & TimerCounter::kCovfs, 0u);
}

// A TIOA edge at a time and what the channel shows after it (SR read once, after RA).
struct Edge {
  uint64_t ticks;  // MCK/1024 ticks since the clock was enabled
  bool level;
  uint32_t sr;  // SR & (status bits | MTIOA), read after the edge
  uint32_t ra, cv;
};

void runEdges(const char* what, uint32_t cmr, const std::vector<Edge>& edges, bool readRa = true) {
  Rig g;
  g.set(kCmr, cmr);
  g.set(kIer, TimerCounter::kEtrgs);
  g.tc.setTioa(1, false);  // the line low before the clock starts: no load, no trigger
  g.set(kCcr, kClken);
  EXPECT_EQ(g.reg(kSr) & 0xFF, 0u) << what;
  for (const Edge& e : edges) {
    g.at(1024 * e.ticks);
    g.tc.setTioa(1, e.level);
    EXPECT_EQ(g.reg(kCv), e.cv) << what << " at " << e.ticks;
    EXPECT_EQ(g.tc.irqLine(1), (e.sr & TimerCounter::kEtrgs) != 0) << what << " at " << e.ticks;
    if (readRa) {
      EXPECT_EQ(g.reg(kRa), e.ra) << what << " at " << e.ticks;
    }
    EXPECT_EQ(g.reg(kSr) & (0xFF | TimerCounter::kMtioa), e.sr) << what << " at " << e.ticks;
  }
}

TEST(TimerCounterModel, CaptureAsLegosTachometerCountsEveryEdge) {
  using T = TimerCounter;
  runEdges("LEGO tacho", kLegoTacho,
           {
               {10, true, T::kEtrgs | T::kLdras | T::kMtioa, 10, 0},  // RA = the count, then the trigger restarts it
               {15, false, T::kEtrgs, 10, 0},                         // falling: trigger only
               {22, true, T::kEtrgs | T::kLdras | T::kMtioa, 7, 0},
               {22 + 3, true, T::kMtioa, 7, 3},  // no edge (the same level): nothing
           });
  runEdges("RA not read between loads: LOVRS", kLegoTacho,
           {
               {10, true, T::kEtrgs | T::kLdras | T::kMtioa, 0, 0},
               {11, false, T::kEtrgs, 0, 0},
               {12, true, T::kEtrgs | T::kLdras | T::kLovrs | T::kMtioa, 0, 0},
           },
           false);
  runEdges("no ABETRG: loads but no trigger", kDiv1024 | etrgedg(kBoth) | ldra(kBoth),
           {
               {10, true, T::kLdras | T::kMtioa, 10, 10},
               {15, false, T::kLdras, 15, 15},
           });
  runEdges("ETRGEDG rising only", kDiv1024 | kAbetrg | etrgedg(kRising),
           {
               {10, true, T::kEtrgs | T::kMtioa, 0, 0},
               {15, false, 0, 0, 5},
           });
  runEdges("LDRB after LDRA, LDBSTOP stops the clock", kDiv1024 | ldra(kRising) | ldrb(kFalling) | (1u << 6),
           {
               {10, true, T::kLdras | T::kMtioa, 10, 10},
               {14, false, T::kLdrbs, 10, 0},  // RB = 14, the clock stopped (CLKSTA low, CV 0)
           });
  runEdges("waveform mode: TIOA is an output, edges do nothing", kWave | kDiv1024 | ldra(kRising),
           {
               {10, true, T::kMtioa, 0, 10},
           });
}

TEST(TimerCounterModel, RbLoadsOnlyAfterRaSinceTheLastTrigger) {
  Rig g;
  g.set(kCmr, kDiv1024 | ldra(kFalling) | ldrb(kRising));
  g.tc.setTioa(1, false);
  g.set(kCcr, kClken);
  g.at(1024 * 5);
  g.tc.setTioa(1, true);  // rising first: RA not loaded yet, so no RB
  EXPECT_EQ(g.reg(kSr) & (TimerCounter::kLdras | TimerCounter::kLdrbs), 0u);
  g.at(1024 * 8);
  g.tc.setTioa(1, false);  // RA = 8
  g.at(1024 * 12);
  g.tc.setTioa(1, true);  // RB = 12
  EXPECT_EQ(g.reg(kSr) & (TimerCounter::kLdras | TimerCounter::kLdrbs), TimerCounter::kLdras | TimerCounter::kLdrbs);
  EXPECT_EQ(g.reg(kRa), 8u);
  EXPECT_EQ(g.reg(kRb), 12u);
}

TEST(TimerCounterModel, CaptureNeedsTheClockAndRaRbAreReadOnlyInCaptureMode) {
  Rig g;
  g.set(kCmr, kLegoTacho);
  g.set(kRa, 0x1234);
  EXPECT_EQ(g.reg(kRa), 0u);
  g.tc.setTioa(1, false);
  g.tc.setTioa(1, true);  // clock never enabled: nothing happens
  EXPECT_EQ(g.reg(kSr) & 0xFF, 0u);
  g.set(kCmr, kWave);
  g.set(kRa, 0x1234);
  EXPECT_EQ(g.reg(kRa), 0x1234u);
  g.set(kCcr, kClken);
  g.set(kCcr, kClkdis | kClken);  // CLKDIS wins
  EXPECT_EQ(g.reg(kSr) & TimerCounter::kClksta, 0u);
}

TEST(TimerCounterModel, PioaPinsFeedEachChannelsTioa) {
  Clock clock;
  TimerCounter tc(clock);
  for (int ch = 0; ch < 3; ++ch) {
    tc.write(0x40 * static_cast<uint32_t>(ch) + kCmr, kLegoTacho);
    tc.write(0x40 * static_cast<uint32_t>(ch) + kCcr, kClken);
  }
  uint32_t levels = 0xFFFFFFFF;
  tc.pinsChanged(levels);
  const int pins[3] = {0, 15, 26};  // TIOA0 = PA0 (motor C), TIOA1 = PA15 (motor A), TIOA2 = PA26 (motor B)
  for (int ch = 0; ch < 3; ++ch) {
    levels &= ~(1u << pins[ch]);
    tc.pinsChanged(levels);
    for (int k = 0; k < 3; ++k) {
      uint32_t sr = 0;
      tc.read(0x40 * static_cast<uint32_t>(k) + kSr, sr);
      EXPECT_EQ((sr & TimerCounter::kEtrgs) != 0, k == ch) << "pin " << pins[ch] << ", channel " << k;
    }
  }
}

}  // namespace
}  // namespace nxtmap::emu::test
