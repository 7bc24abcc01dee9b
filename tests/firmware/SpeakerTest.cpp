// The speaker driver against a fake SSC + PDC: the divider LEGO's tone layout needs (512 bit times per
// period), the words queued per buffer until the duration's periods are out, and silence on stop.
#include <gtest/gtest.h>

#include "firmware/drivers/Speaker.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {

constexpr uint32_t kMck = 48054857;

TEST(Speaker, DividerIsTheNearestForLegosPeriodOf512Bits) {
  struct Row {
    uint16_t hz;
    uint32_t div;
  };
  // MCK / (1024 x Hz): 213.3, 106.7, 46.9, 15.6, 3.33; below 220 and above 14080 clamped.
  const Row rows[] = {{220, 213}, {440, 107}, {1000, 47}, {3000, 16}, {14080, 3}, {100, 213}, {20000, 3}};
  for (const Row& r : rows) EXPECT_EQ(Speaker<FakeBus>::divider(kMck, r.hz), r.div) << r.hz << " Hz";
}

// Plays and answers every ENDTX / TXBUFE as the PDC would; returns the words queued (TCR + TNCR writes).
struct Rig {
  FakeBus bus;
  Speaker<FakeBus> speaker{bus};
  uint32_t queued() const {
    uint32_t n = 0;
    for (const auto& w : bus.writes)
      if (w.first == ssc::kTcr || w.first == ssc::kTncr) n += w.second;
    return n;
  }
  // The PDC sent everything queued: ENDTX and TXBUFE; the driver's interrupt runs while enabled.
  void drain() {
    bus.regs[ssc::kSr] = ssc::kSrEndtx | ssc::kSrTxbufe;
    for (int i = 0; i < 100000 && speaker.playing(); ++i) speaker.onInterrupt();
  }
};

TEST(Speaker, QueuesTheDurationsPeriodsSixteenWordsEach) {
  struct Row {
    uint16_t hz, ms;
    uint32_t words;
  };
  const Row rows[] = {
      {1000, 200, 200 * 16}, {440, 100, 44 * 16},
      {3000, 50, 150 * 16},  {1000, 3, 10 * 16},  // at least 10 ms (LEGO's minimum)
      {300, 10, 3 * 16},                          // 3 periods: a last buffer of one
      {0, 100, 100 * 16},                         // 0 Hz: silence for the duration (1 kHz words, TD left to the PIO)
  };
  for (const Row& r : rows) {
    Rig g;
    g.speaker.init();
    g.bus.writes.clear();
    g.speaker.play(kMck, r.hz, r.ms);
    EXPECT_TRUE(g.speaker.playing());
    g.drain();
    EXPECT_FALSE(g.speaker.playing()) << r.hz << " Hz " << r.ms << " ms";
    EXPECT_EQ(g.queued(), r.words) << r.hz << " Hz " << r.ms << " ms";
    const auto pdr = g.bus.writesTo(reg::kPioPdr);
    EXPECT_EQ(pdr.size(), r.hz == 0 ? 0u : 1u) << "TD to the SSC only for a tone";
    EXPECT_EQ(g.bus.writesTo(reg::kPioPer).back(), ssc::kPinTd) << "TD back to the PIO at the end";
  }
}

TEST(Speaker, StopDropsTheQueuedWordsAndTheInterrupt) {
  Rig g;
  g.speaker.init();
  g.speaker.play(kMck, 440, 3000);
  g.bus.writes.clear();
  g.speaker.stop();
  EXPECT_FALSE(g.speaker.playing());
  EXPECT_EQ(g.bus.regs[ssc::kTcr], 0u);
  EXPECT_EQ(g.bus.regs[ssc::kTncr], 0u);
  EXPECT_EQ(g.bus.regs[ssc::kPtcr], ssc::kPtcrTxtdis);
  EXPECT_EQ(g.bus.regs[ssc::kIdr], ssc::kSrEndtx | ssc::kSrTxbufe);
  g.bus.writes.clear();
  g.bus.regs[ssc::kSr] = ssc::kSrEndtx;
  g.speaker.onInterrupt();  // a late interrupt after the stop queues nothing
  EXPECT_EQ(g.queued(), 0u);
}

}  // namespace
}  // namespace nxtmap::fw::test
