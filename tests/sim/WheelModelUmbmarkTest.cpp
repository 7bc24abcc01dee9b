// WheelModel against UMBmark: Eb and Ed with their per-robot signs, the presets' magnitudes of them, and the
// UMBmark square they leave open.
#include "host/sim/WheelModel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/sim/NxtWheels.hpp"

namespace nxtmap::sim {
namespace {

using test::kD;
using test::kPi;
using test::kTrack;

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
