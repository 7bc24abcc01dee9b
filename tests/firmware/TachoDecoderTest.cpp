#include <gtest/gtest.h>

#include "firmware/board/At91sam7s.hpp"
#include "firmware/drivers/TachoDecoder.hpp"

namespace nxtmap::fw {
namespace {
using namespace reg;

constexpr TachoDecoder::Pins kPins[3] = {{kPinTachoA, kPinDirA}, {kPinTachoB, kPinDirB}, {kPinTachoC, kPinDirC}};

// Drives motor A's encoder: `edges` pulse edges; forward = the pulse pin changes to differ from the
// direction pin (the quadrature phase of a forward turn).
void turn(TachoDecoder& t, uint32_t& levels, int edges, bool forward, bool tickEach = true) {
  for (int i = 0; i < edges; ++i) {
    levels ^= kPinTachoA;
    const bool pulse = (levels & kPinTachoA) != 0;
    // Forward: the direction pin is at the opposite level of the pulse pin after its edge.
    if (forward) {
      if (pulse)
        levels &= ~kPinDirA;
      else
        levels |= kPinDirA;
    } else {
      if (pulse)
        levels |= kPinDirA;
      else
        levels &= ~kPinDirA;
    }
    t.onPinChange(levels, kPinTachoA);
    if (tickEach) t.tick();
  }
}

TEST(TachoDecoder, CountsOneDegreePerPulseEdgeWithDirection) {
  TachoDecoder t(kPins);
  uint32_t levels = 0;
  turn(t, levels, 360, true);
  EXPECT_EQ(t.count(0), 360);
  turn(t, levels, 90, false);
  EXPECT_EQ(t.count(0), 270);
  EXPECT_EQ(t.count(1), 0);
  EXPECT_FALSE(t.fault());
}

TEST(TachoDecoder, OnlyThePulsePinThatChangedCounts) {
  TachoDecoder t(kPins);
  // Motor B's direction pin and motor C's pulse pin change; only C counts.
  t.onPinChange(kPinDirB | kPinTachoC, kPinDirB | kPinTachoC);
  EXPECT_EQ(t.count(0), 0);
  EXPECT_EQ(t.count(1), 0);
  EXPECT_EQ(t.count(2), 1);  // pulse high, dir low: forward
  t.onPinChange(kPinTachoC | kPinDirC | kPinTachoB, kPinTachoB);
  EXPECT_EQ(t.count(1), 1);
  EXPECT_EQ(t.pulseMask(), kPinTachoA | kPinTachoB | kPinTachoC);
}

TEST(TachoDecoder, AnEdgeStormWithinOneMillisecondIsAFault) {
  TachoDecoder t(kPins);
  uint32_t levels = 0;
  turn(t, levels, TachoDecoder::kMaxEdgesPerMs, true, false);
  EXPECT_FALSE(t.fault());
  t.tick();
  turn(t, levels, TachoDecoder::kMaxEdgesPerMs + 1, true, false);
  EXPECT_TRUE(t.fault());
  t.clearFault();
  EXPECT_FALSE(t.fault());
}

}  // namespace
}  // namespace nxtmap::fw
