// PoseTracker's wheel states (WheelCalibration): a robot whose drives curve or whose turns are off by a
// fixed factor is measured against walls; the tracker learns both, keeps them across resets and is not
// taught by a reading far from its prediction.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>

#include "common/motion/PoseTracker.hpp"

namespace nxtmap {
namespace {

// A robot that drives `drives` times 200 mm North, its heading changing by driftUradPerM per metre; after
// every drive a straight wall beside it tells its heading to 3 mrad (1 sigma). The robot is never levelled:
// the heading error grows along the run and the tracker must predict it.
WheelCalibration learnDrift(int32_t driftUradPerM, int drives) {
  PoseTracker t;
  double trueHeadingMrad = 0;
  for (int i = 0; i < drives; ++i) {
    t.drove(200, Dir::North);
    trueHeadingMrad += driftUradPerM * 0.2 / 1000.0;
    (void)t.measureHeading(static_cast<int32_t>(trueHeadingMrad >= 0 ? trueHeadingMrad + 0.5 : trueHeadingMrad - 0.5), 9);
  }
  return t.wheels();
}

TEST(PoseTrackerWheels, ADriveThatCurvesIsLearntFromTheWallsBesideIt) {
  const struct {
    int32_t truth;  // urad/m
    int32_t within;
  } table[] = {{35000, 2000}, {-35000, 2000}, {17000, 2000}, {-8700, 2000}, {0, 2000}};
  for (const auto& row : table) {
    const WheelCalibration w = learnDrift(row.truth, 20);  // 4 m
    EXPECT_NEAR(w.driftUradPerM, row.truth, row.within) << row.truth;
    // From 35,000^2: what is left is the heading's own random walk per drive (PoseNoise::driveMradPerCell).
    EXPECT_LT(w.driftVariance, 8000LL * 8000) << row.truth;
    EXPECT_EQ(w.turnPpm, 0) << row.truth;                    // nothing was turned
  }
}

// A robot whose turns go (1 + e) times as far as told: it turns `quarters` quarter turns clockwise, told
// 1571 mrad each, and after each a wall across it tells its heading to 3 mrad.
int32_t learnTurn(int32_t truthPpm, int quarters) {
  PoseTracker t;
  double trueHeadingMrad = 0;
  int32_t handed = 0;  // the turn error taken by the caller (who corrects its commands by it)
  for (int i = 0; i < quarters; ++i) {
    // Told 1571 / (1 + handed); turned that times (1 + truth); reported as told, times (1 + handed).
    const double told = 1571.0 / (1.0 + handed * 1e-6);
    trueHeadingMrad += told * (1.0 + truthPpm * 1e-6) - 1570.796;
    t.rotated(1571, 1);
    (void)t.measureHeading(static_cast<int32_t>(trueHeadingMrad >= 0 ? trueHeadingMrad + 0.5 : trueHeadingMrad - 0.5), 9);
    handed += t.takeTurnPpm();
  }
  return handed + t.wheels().turnPpm;
}

TEST(PoseTrackerWheels, TurnsThatGoTooFarOrShortAreLearntFromTheWallsAfterThem) {
  // A known track-width error is recovered within 0.5 % (5,000 ppm) after 8 quarter turns, 0.1 % after 40.
  const int32_t truths[] = {20000, -20000, 12000, -5000, 0};
  for (const int32_t truth : truths) {
    EXPECT_NEAR(learnTurn(truth, 8), truth, 5000) << truth;
    EXPECT_NEAR(learnTurn(truth, 40), truth, 1000) << truth;
  }
}

TEST(PoseTrackerWheels, WhatWasLearntOutlivesAReset) {
  PoseTracker t;
  for (int i = 0; i < 20; ++i) {
    t.drove(200, Dir::North);
    (void)t.measureHeading((i + 1) * 7, 9);  // 35 mrad/m
  }
  const WheelCalibration before = t.wheels();
  ASSERT_GT(before.driftUradPerM, 30000);
  t.reset();
  EXPECT_EQ(t.thetaMrad(), 0);
  EXPECT_EQ(t.thetaVariance(), 0);
  EXPECT_EQ(t.wheels().driftUradPerM, before.driftUradPerM);
  EXPECT_EQ(t.wheels().driftVariance, before.driftVariance);
  // And the next drive is predicted to curve by it: 35 mrad/m over 400 mm is 14 mrad.
  EXPECT_NEAR(t.driftMrad(400), 14, 1);
  t.drove(400, Dir::North);
  EXPECT_NEAR(t.thetaMrad(), 14, 1);
}

TEST(PoseTrackerWheels, AReadingFarFromItsPredictionCorrectsThePoseButTeachesTheWheelsNothing) {
  PoseNoise noise;
  noise.turnMradPerQuarter = 30;
  PoseTracker t(noise);
  t.rotated(1571, 1);
  t.drove(500, Dir::East);
  const WheelCalibration before = t.wheels();
  // 2.5 sigma out (sigma about 49 mrad: the turn's 30, the turn error's 31, the drift's 17, the drive's 15):
  // taken for the pose, not for the wheels.
  ASSERT_TRUE(t.measureHeading(120, 9));
  EXPECT_GT(t.thetaMrad(), 90);
  EXPECT_EQ(t.wheels().driftUradPerM, before.driftUradPerM);
  EXPECT_EQ(t.wheels().turnPpm, before.turnPpm);
  // Within 1 sigma it teaches them.
  PoseTracker u(noise);
  u.rotated(1571, 1);
  u.drove(500, Dir::East);
  ASSERT_TRUE(u.measureHeading(20, 9));
  EXPECT_NE(u.wheels().driftUradPerM, 0);
  EXPECT_NE(u.wheels().turnPpm, 0);
}

TEST(PoseTrackerWheels, ATurnCalibrationFixesTheTurnErrorsVariance) {
  PoseTracker t;
  t.knowTurn(3000LL * 3000);
  EXPECT_EQ(t.wheels().turnPpm, 0);
  EXPECT_EQ(t.wheels().turnVariance, 3000LL * 3000);
  EXPECT_EQ(t.wheels().driftVariance, WheelCalibration{}.driftVariance);  // untouched
}

TEST(PoseTrackerWheels, AStoredCalibrationIsWhereLearningStarts) {
  WheelCalibration stored;
  stored.driftUradPerM = -12000;
  stored.driftVariance = 2000LL * 2000;
  stored.turnPpm = 7000;
  stored.turnVariance = 1000LL * 1000;
  const PoseTracker t(PoseNoise{}, stored);
  const WheelCalibration w = t.wheels();
  EXPECT_EQ(w.driftUradPerM, -12000);
  EXPECT_EQ(w.driftVariance, 2000LL * 2000);
  EXPECT_EQ(w.turnPpm, 7000);
  EXPECT_EQ(w.turnVariance, 1000LL * 1000);
  EXPECT_EQ(t.driftMrad(1000), -12);
}

}  // namespace
}  // namespace nxtmap

namespace nxtmap {
namespace {

TEST(PoseTrackerWheels, WhatIsLearntStaysWithinWhatWheelsDo) {
  // A store that already says 190 mrad/m (11 deg/m) and is unsure of it; readings that say still more.
  WheelCalibration stored;
  stored.driftUradPerM = 190000;
  stored.driftVariance = 100000LL * 100000;
  PoseTracker t(PoseNoise{}, stored);
  for (int i = 0; i < 10; ++i) {
    t.drove(500, Dir::North);
    (void)t.measureHeading(t.thetaMrad() + 40, 9);
  }
  EXPECT_LE(t.wheels().driftUradPerM, 200000);
  EXPECT_GT(t.wheels().driftUradPerM, 190000);
}

}  // namespace
}  // namespace nxtmap
