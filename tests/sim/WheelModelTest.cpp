// WheelModel: the typical model draw for draw against the published formulas, UMBmark's Eb and Ed with
// their per-robot signs, backlash, encoder counts and the UMBmark square.
#include "host/sim/WheelModel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace nxtmap::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kD = kNxtWheelDiameterCm;
constexpr double kTrack = kNxtTrackCm;
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

// --- UMBmark: Eb and Ed, their per-robot signs ---------------------------------------------------------

class WheelModelTrack : public ::testing::TestWithParam<double> {};

TEST_P(WheelModelTrack, EbScalesA90DegreeSpinByOneOverEb) {
  WheelNoise w;
  w.trackError = GetParam();
  int longer = 0, shorter = 0;
  for (uint64_t seed = 1; seed <= 16; ++seed) {
    WheelModel wheels(w, kD, kTrack, seed);
    std::mt19937_64 rng(seed);
    const double eb = wheels.trackRatio();
    EXPECT_NEAR(std::abs(eb - 1.0), GetParam(), 1e-12);
    EXPECT_NEAR(wheels.trackCm(), kTrack * eb, 1e-12);
    EXPECT_NEAR(wheels.spin(90.0, rng).headingChangeDeg, 90.0 / eb, 1e-9);
    EXPECT_NEAR(wheels.spin(-90.0, rng).headingChangeDeg, -90.0 / eb, 1e-9);
    EXPECT_EQ(WheelModel(w, kD, kTrack, seed).trackRatio(), eb);  // the seed alone fixes the sign
    (eb > 1.0 ? longer : shorter) += 1;
  }
  EXPECT_GT(longer, 0);
  EXPECT_GT(shorter, 0);
}

INSTANTIATE_TEST_SUITE_P(Magnitudes, WheelModelTrack, ::testing::Values(0.005, 0.02, 0.04));

class WheelModelDrift : public ::testing::TestWithParam<double> {};

TEST_P(WheelModelDrift, EdDriftsTheStatedDegreesPerMetreWithTheSignOfTheSeed) {
  const double degPerM = GetParam();
  WheelNoise w;
  w.diameterRatioError = diameterRatioErrorForDrift(degPerM, kTrack);
  EXPECT_NEAR(driftDegPerMetre(w.diameterRatioError, kTrack), degPerM, 1e-12);
  int left = 0, right = 0;
  for (uint64_t seed = 1; seed <= 16; ++seed) {
    WheelModel wheels(w, kD, kTrack, seed);
    std::mt19937_64 rng(seed);
    const double ed = wheels.diameterRatio();
    EXPECT_NEAR(std::abs(ed - 1.0), w.diameterRatioError, w.diameterRatioError * w.diameterRatioError);
    // Ed > 1: the right wheel rolls farther, the robot curves left (counter-clockwise, negative).
    const double expected = ed > 1.0 ? -degPerM : degPerM;
    const WheelStep s = wheels.straight(100.0, rng);
    EXPECT_NEAR(s.headingChangeDeg, expected, 1e-9);
    EXPECT_NEAR(s.distanceCm, 100.0, 1e-9);  // the mean diameter is nominal
    EXPECT_NEAR(wheels.straight(-50.0, rng).headingChangeDeg, -expected / 2.0, 1e-9);
    (ed > 1.0 ? left : right) += 1;
  }
  EXPECT_GT(left, 0);
  EXPECT_GT(right, 0);
}

INSTANTIATE_TEST_SUITE_P(DegPerMetre, WheelModelDrift, ::testing::Values(0.5, 2.0, 4.0));

TEST(WheelModel, ThePresetsCarryTheStatedMagnitudes) {
  const WheelNoise nxt = wheelPreset("nxt"), raw = wheelPreset("nxt-uncalibrated");
  EXPECT_NEAR(raw.trackError, 0.02, 1e-12);
  EXPECT_NEAR(driftDegPerMetre(raw.diameterRatioError, kTrack), 2.0, 1e-12);
  EXPECT_NEAR(nxt.trackError, raw.trackError / 4.0, 1e-12);
  EXPECT_NEAR(nxt.diameterRatioError, raw.diameterRatioError / 4.0, 1e-12);
  for (const WheelNoise& w : {nxt, raw}) {
    EXPECT_EQ(w.backlashDeg, 2.0);
    EXPECT_EQ(w.encoderDeg, 1.0);
  }
  const WheelNoise ideal = wheelPreset("ideal");
  EXPECT_EQ(ideal.slipSigma + ideal.turnSigmaDeg + ideal.encoderDeg + ideal.backlashDeg + ideal.diameterRatioError +
                ideal.trackError,
            0.0);
  EXPECT_EQ(describeWheels(raw).size(), 6u);
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

// --- the UMBmark square -------------------------------------------------------------------------------

struct Pose {
  double x = 0.0, y = 0.0, h = 0.0;  // cm, y down; compass heading, degrees clockwise from N
};

void apply(Pose& p, double distanceCm, double turnDeg) {
  // An arc of distanceCm turning evenly by turnDeg: its chord runs along the mid heading.
  const double phi = turnDeg * kPi / 180.0;
  const double chord = std::abs(phi) < 1e-12 ? distanceCm : 2.0 * distanceCm / phi * std::sin(phi / 2.0);
  const double mid = (p.h + turnDeg / 2.0) * kPi / 180.0;
  p.x += chord * std::sin(mid);
  p.y -= chord * std::cos(mid);
  p.h += turnDeg;
}

// UMBmark's 1 m square, four legs and four 90 degree spins in `dir` (+1 clockwise, -1 counter-clockwise).
Pose square(WheelModel& wheels, int dir) {
  std::mt19937_64 rng(1);
  Pose p;
  for (int leg = 0; leg < 4; ++leg) {
    const WheelStep a = wheels.straight(100.0, rng);
    apply(p, a.distanceCm, a.headingChangeDeg);
    const WheelStep b = wheels.spin(90.0 * dir, rng);
    apply(p, b.distanceCm, b.headingChangeDeg);
  }
  return p;
}

TEST(WheelModelSquare, IdealClosesInBothDirections) {
  for (int dir : {1, -1}) {
    WheelModel ideal(wheelPreset("ideal"), kD, kTrack, 1);
    const Pose closed = square(ideal, dir);
    EXPECT_NEAR(closed.x, 0.0, 1e-9);
    EXPECT_NEAR(closed.y, 0.0, 1e-9);
    EXPECT_NEAR(closed.h, 360.0 * dir, 1e-9);
  }
}

class WheelModelSquare : public ::testing::TestWithParam<uint64_t> {};

TEST_P(WheelModelSquare, UncalibratedMissesByItsEbAndEd) {
  const uint64_t seed = GetParam();
  WheelNoise w = wheelPreset("nxt-uncalibrated");
  w.slipSigma = w.turnSigmaDeg = w.encoderDeg = w.backlashDeg = 0.0;  // the systematic part alone
  double worstMissCm = 0.0;
  for (int dir : {1, -1}) {
    WheelModel wheels(w, kD, kTrack, seed);
    const Pose miss = square(wheels, dir);
    // The expectation from the stated figures alone: each leg an arc drifting 2 degrees per metre of
    // the nominal track against Ed's sign (over the actual track: / Eb), each turn 90 / Eb, during
    // which the larger wheel pushes the centre by half the wheels' difference of arc.
    const double eb = wheels.trackRatio();
    const double edSign = wheels.diameterRatio() > 1.0 ? 1.0 : -1.0;
    const double drift = -edSign * 2.0 / eb;
    const double armCm = 90.0 * dir * kPi / 180.0 * kTrack / 2.0;
    Pose expected;
    for (int leg = 0; leg < 4; ++leg) {
      apply(expected, 100.0, drift);
      apply(expected, -edSign * w.diameterRatioError * armCm / 2.0, 90.0 * dir / eb);
    }
    EXPECT_NEAR(miss.x, expected.x, 1e-6) << "dir " << dir;
    EXPECT_NEAR(miss.y, expected.y, 1e-6) << "dir " << dir;
    EXPECT_NEAR(miss.h, expected.h, 1e-9) << "dir " << dir;
    worstMissCm = std::max(worstMissCm, std::hypot(miss.x, miss.y));
  }
  // UMBmark's point: Ed and Eb may cancel in one direction, never in both; the worse direction is left
  // open by more than a hand's width.
  EXPECT_GT(worstMissCm, 10.0);
}

INSTANTIATE_TEST_SUITE_P(Seeds, WheelModelSquare, ::testing::Values(1u, 2u, 3u, 4u, 5u, 6u));

}  // namespace
}  // namespace nxtmap::sim
