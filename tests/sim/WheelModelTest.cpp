// WheelModel: the typical model draw for draw against the published formulas, the systematic fields drawing no
// random numbers, backlash and encoder counts.
#include "host/sim/WheelModel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tests/sim/NxtWheels.hpp"

namespace nxtmap::sim {
namespace {

using test::kD;
using test::kPi;
using test::kTrack;

constexpr double kCmPerDeg = kPi * kD / 360.0;

WheelNoise only(double slip, double turn) {
  WheelNoise w;
  w.slipSigma = slip;
  w.turnSigmaDeg = turn;
  return w;
}

// The published SimRobot's formulas (before WheelModel), drawing from the same kind of stream.
double gaussian(double sigma, std::mt19937_64& rng) {
  return sigma > 0.0 ? std::normal_distribution<double>(0.0, sigma)(rng) : 0.0;
}

enum class Cmd { Straight, Spin, Eighths };
struct Command {
  Cmd kind;
  double value;  // cm, degrees or eighths
};
const std::vector<Command> kScript{{Cmd::Straight, 10.0}, {Cmd::Spin, 90.0},    {Cmd::Straight, -20.0},
                                   {Cmd::Eighths, 2},     {Cmd::Spin, -7.5},    {Cmd::Eighths, -4},
                                   {Cmd::Spin, 0.0},      {Cmd::Straight, 0.0}, {Cmd::Spin, 270.0}};

WheelStep run(WheelModel& w, const Command& c, std::mt19937_64& rng) {
  switch (c.kind) {
    case Cmd::Straight: return w.straight(c.value, rng);
    case Cmd::Spin: return w.spin(c.value, rng);
    default: return w.turnEighths(static_cast<int>(c.value), rng);
  }
}

struct PublishedCase {
  double slip, turn;
  uint64_t seed;
};
class WheelModelPublished : public ::testing::TestWithParam<PublishedCase> {};

TEST_P(WheelModelPublished, TypicalReproducesThePublishedFormulasDrawForDraw) {
  const PublishedCase p = GetParam();
  WheelModel wheels(only(p.slip, p.turn), kD, kTrack, p.seed);
  std::mt19937_64 rng(p.seed), ref(p.seed);
  for (const Command& c : kScript) {
    const WheelStep s = run(wheels, c, rng);
    if (c.kind == Cmd::Straight) {
      EXPECT_EQ(s.distanceCm, c.value * (1.0 + gaussian(p.slip, ref)));
      EXPECT_EQ(s.headingChangeDeg, 0.0);
    } else {
      const double deg = c.kind == Cmd::Spin ? c.value : 45.0 * c.value;
      const double sigma = c.kind == Cmd::Spin ? p.turn * std::max(0.25, std::abs(c.value) / 90.0) : p.turn;
      const double noise = gaussian(sigma, ref);
      EXPECT_EQ(s.headingWheelsDeg, deg);
      EXPECT_EQ(s.headingNoiseDeg, noise);
      EXPECT_EQ(s.headingChangeDeg, deg + noise);
      EXPECT_EQ(s.distanceCm, 0.0);
    }
  }
  EXPECT_EQ(rng(), ref());  // the same number of draws
}

INSTANTIATE_TEST_SUITE_P(Presets, WheelModelPublished,
                         ::testing::Values(PublishedCase{0.01, 0.5, 1}, PublishedCase{0.01, 0.5, 77},
                                           PublishedCase{0.03, 2.0, 5}, PublishedCase{0.0, 0.0, 3},
                                           PublishedCase{0.02, 0.0, 9}));

TEST(WheelModel, TypicalPresetIsTheRandomPartOnly) {
  const WheelNoise t = wheelPreset("typical");
  EXPECT_EQ(t.slipSigma, 0.01);
  EXPECT_EQ(t.turnSigmaDeg, 0.5);
  EXPECT_EQ(t.encoderDeg + t.backlashDeg + t.diameterRatioError + t.trackError, 0.0);
}

TEST(WheelModel, SystematicFieldsDrawNoRandomNumbers) {
  WheelNoise w = wheelPreset("harsh");
  w.slipSigma = 0.0;
  w.turnSigmaDeg = 0.0;
  WheelModel wheels(w, kD, kTrack, 4);
  std::mt19937_64 rng(4), untouched(4);
  for (const Command& c : kScript) run(wheels, c, rng);
  double l = 0.0, r = 0.0;
  wheels.arcs(3.0, -3.0, l, r);
  wheels.newStretch(false, rng);
  wheels.newStretch(true, rng);
  EXPECT_EQ(wheels.stretchTurnNoiseDeg(5.0), 0.0);
  EXPECT_EQ(rng(), untouched());
}

// --- backlash and encoder counts ----------------------------------------------------------------------

struct BacklashCase {
  double backlashDeg;
  double firstCm, secondCm;
  double lostWheelDeg;  // of the second move, on each wheel
};
class WheelModelBacklash : public ::testing::TestWithParam<BacklashCase> {};

TEST_P(WheelModelBacklash, LosesThePlayAtAReversalAndNothingWhenContinuing) {
  const BacklashCase c = GetParam();
  WheelNoise w;
  w.backlashDeg = c.backlashDeg;
  WheelModel wheels(w, kD, kTrack, 1);
  std::mt19937_64 rng(1);
  wheels.straight(c.firstCm, rng);
  const WheelStep s = wheels.straight(c.secondCm, rng);
  const double expected = std::copysign(std::abs(c.secondCm) - c.lostWheelDeg * kCmPerDeg, c.secondCm);
  EXPECT_NEAR(s.distanceCm, expected, 1e-9);
  EXPECT_NEAR(s.headingChangeDeg, 0.0, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Moves, WheelModelBacklash,
                         ::testing::Values(BacklashCase{2.0, 10.0, 10.0, 0.0}, BacklashCase{2.0, 10.0, -10.0, 2.0},
                                           BacklashCase{2.0, -10.0, -10.0, 0.0}, BacklashCase{2.0, -10.0, 10.0, 2.0},
                                           BacklashCase{4.0, 5.0, -5.0, 4.0}, BacklashCase{0.0, 10.0, -10.0, 0.0}));

TEST(WheelModel, BacklashShortensASpinAfterAForwardDriveOnTheReversedWheelOnly) {
  WheelNoise w;
  w.backlashDeg = 2.0;
  WheelModel wheels(w, kD, kTrack, 1);
  std::mt19937_64 rng(1);
  wheels.straight(10.0, rng);
  // Clockwise: the left wheel keeps going forward, the right one reverses and loses 2 degrees.
  const double lostDeg = 2.0 * kCmPerDeg / kTrack * 180.0 / kPi;
  EXPECT_NEAR(wheels.spin(90.0, rng).headingChangeDeg, 90.0 - lostDeg, 1e-9);
  // Back again: now both wheels reverse.
  EXPECT_NEAR(wheels.spin(-90.0, rng).headingChangeDeg, -90.0 + 2.0 * lostDeg, 1e-9);
}

TEST(WheelModel, EmulatorArcsTakeUpThePlayDegreeByDegree) {
  WheelNoise w;
  w.backlashDeg = 2.0;
  WheelModel wheels(w, kD, kTrack, 1);
  // Left: forward, forward, then back 1 degree at a time; right: steadily forward.
  const std::vector<double> leftDeg{1, 1, -1, -1, -1, -1, 1};
  const std::vector<double> leftMoves{1, 1, 0, 0, -1, -1, 0};
  for (size_t i = 0; i < leftDeg.size(); ++i) {
    double l = 0.0, r = 0.0;
    wheels.arcs(leftDeg[i], 1.0, l, r);
    EXPECT_NEAR(l, leftMoves[i] * kCmPerDeg, 1e-12) << "step " << i;
    EXPECT_NEAR(r, kCmPerDeg, 1e-12) << "step " << i;
  }
}

class WheelModelCounts : public ::testing::TestWithParam<double> {};

TEST_P(WheelModelCounts, ThePilotStopsOnWholeEncoderCounts) {
  WheelNoise w;
  w.encoderDeg = 1.0;
  WheelModel wheels(w, kD, kTrack, 1);
  std::mt19937_64 rng(1);
  const double cm = GetParam();
  const double wheelDeg = wheels.straight(cm, rng).distanceCm / kCmPerDeg;
  EXPECT_NEAR(wheelDeg, std::round(wheelDeg), 1e-9);
  EXPECT_NEAR(wheelDeg, std::round(cm / kCmPerDeg), 1e-9);
  // A spin of cm degrees: each wheel turns a whole number of degrees too.
  const double spinWheelDeg = wheels.spin(cm, rng).headingChangeDeg * kPi / 180.0 * kTrack / 2.0 / kCmPerDeg;
  EXPECT_NEAR(spinWheelDeg, std::round(spinWheelDeg), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Distances, WheelModelCounts, ::testing::Values(10.0, 20.0, 7.3, -13.1, 0.02, 100.0));

}  // namespace
}  // namespace nxtmap::sim
