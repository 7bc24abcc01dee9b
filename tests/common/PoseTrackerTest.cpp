// PoseTracker: the integer Kalman filter of the robot's offset from its believed cell and its
// heading error, from tables of motions and measurements.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/motion/PoseTracker.hpp"

namespace nxtmap {
namespace {

TEST(PoseTracker, StartsExactlyAtTheCentre) {
  PoseTracker t;
  t.reset();
  EXPECT_EQ(t.xMm(), 0);
  EXPECT_EQ(t.yMm(), 0);
  EXPECT_EQ(t.thetaMrad(), 0);
  EXPECT_EQ(t.varianceAlong(Dir::North), 0);
  EXPECT_EQ(t.thetaVariance(), 0);
}

struct Motion {
  int32_t rotateMrad;   // rotation carried out
  int quarters;         // believed quarter turns
  int32_t driveMm;      // then driven
  Dir heading;          // believed heading while driving
  int32_t x, y, theta;  // expected estimate afterwards (mm, mm, mrad)
};

class PoseTrackerMotion : public ::testing::TestWithParam<Motion> {};

TEST_P(PoseTrackerMotion, DeadReckonsSmallAngles) {
  const Motion m = GetParam();
  PoseTracker t;
  t.rotated(m.rotateMrad, m.quarters);
  t.drove(m.driveMm, m.heading);
  EXPECT_EQ(t.xMm(), m.x);
  EXPECT_EQ(t.yMm(), m.y);
  EXPECT_EQ(t.thetaMrad(), m.theta);
}

INSTANTIATE_TEST_SUITE_P(Table, PoseTrackerMotion,
                         ::testing::Values(Motion{0, 0, 100, Dir::North, 0, 100, 0},       // straight ahead
                                           Motion{0, 0, -100, Dir::North, 0, -100, 0},     // straight back
                                           Motion{20, 0, 100, Dir::North, 2, 100, 20},     // 20 mrad right: drifts east
                                           Motion{-30, 0, 200, Dir::North, -6, 200, -30},  // left: drifts west
                                           Motion{1571 + 10, 1, 100, Dir::East, 100, -1,
                                                  10},  // quarter right, a bit more: south
                                           Motion{-1571, -1, 100, Dir::West, -100, 0, 0},   // quarter left, exact
                                           Motion{3142, 2, 100, Dir::South, 0, -100, 0}));  // half turn

TEST(PoseTracker, TurnsAndDrivingMakeItUncertain) {
  PoseTracker t;
  t.rotated(1571, 1);
  const int64_t afterTurn = t.thetaVariance();
  EXPECT_GT(afterTurn, 0);
  t.drove(500, Dir::East);
  EXPECT_GT(t.varianceAlong(Dir::East), 0);   // slip along the track
  EXPECT_GT(t.varianceAlong(Dir::North), 0);  // heading error across it
  EXPECT_GT(t.thetaVariance(), afterTurn);
}

TEST(PoseTracker, RebaseMovesTheReferenceCentre) {
  PoseTracker t;
  t.drove(103, Dir::North);
  t.rebase(Dir::North, 1, 100);
  EXPECT_EQ(t.yMm(), 3);
  t.drove(-98, Dir::North);
  t.rebase(Dir::North, -1, 100);
  EXPECT_EQ(t.yMm(), 5);
}

TEST(PoseTracker, AReadingPullsTheOffsetAndTheHeading) {
  PoseNoise noise;
  noise.turnMradPerQuarter = 50;  // a poor turn: the heading is uncertain
  for (const Dir wall : {Dir::South, Dir::North}) {
    PoseTracker t(noise);
    t.rotated(1571, 1);  // now facing East
    for (int i = 0; i < 5; ++i) {
      t.drove(100, Dir::East);
      t.rebase(Dir::East, 1, 100);
    }
    // A wall says the robot is 25 mm south of where it believes: so it was heading right of East.
    const int32_t towardsWall = wall == Dir::South ? 25 : -25;
    ASSERT_TRUE(t.measure(wall, towardsWall));
    EXPECT_LT(t.yMm(), -12) << "wall " << static_cast<int>(wall);
    EXPECT_GE(t.yMm(), -25);
    EXPECT_GT(t.thetaMrad(), 0);
    EXPECT_EQ(t.xMm(), 0);
  }
}

TEST(PoseTracker, GateRefusesReadingsThatCannotBeTheKnownWall) {
  PoseTracker t;
  t.rotated(1571, 1);
  t.drove(300, Dir::East);
  EXPECT_FALSE(t.measure(Dir::North, 60));   // beyond the 40 mm gate
  EXPECT_FALSE(t.measure(Dir::North, -95));  // a cell short: another obstacle
  EXPECT_EQ(t.rejected(), 2u);
  EXPECT_TRUE(t.measure(Dir::North, 5));
  EXPECT_EQ(t.accepted(), 1u);
}

TEST(PoseTracker, AStraightWallFaceCorrectsADriftTheGateWouldRefuseWhenTheFilterIsThatUnsure) {
  // After a quarter turn and `cells` cells driven East with nothing read, the North wall is read
  // `offset` mm off the prediction: the 40 mm gate refuses it, unless the wall is a straight face and
  // the offset lies within 2 sigma of the filter's own uncertainty and the 120 mm wide gate.
  struct Case {
    const char* what;
    int cells;
    int32_t offset;
    bool straight;
    bool accepted;
  };
  const Case cases[] = {
      {"3 m unseen, a straight face 80 mm off", 30, 80, true, true},
      {"3 m unseen, a straight face 80 mm short", 30, -80, true, true},
      {"3 m unseen, a wall that is not a straight face", 30, 80, false, false},
      {"3 m unseen, beyond the wide gate", 30, 130, true, false},
      {"30 cm driven: the filter is sure, 60 mm is another obstacle", 3, 60, true, false},
      {"30 cm driven, within the ordinary gate", 3, 10, false, true},
  };
  for (const Case& c : cases) {
    PoseTracker t;
    t.rotated(1571, 1);
    for (int i = 0; i < c.cells; ++i) t.drove(100, Dir::East);
    EXPECT_EQ(t.measure(Dir::North, c.offset, 0, c.straight), c.accepted)
        << c.what << " (sigma " << std::sqrt(static_cast<double>(t.varianceAlong(Dir::North))) << " mm)";
    if (c.accepted) {
      EXPECT_GT(t.yMm() * c.offset, 0) << c.what;
    }
  }
}

TEST(PoseTracker, ASecondStraightFaceConfirmsARefusedOffset) {
  // A sure filter (30 cm driven East) reads walls far off the prediction, one after another: a
  // straight face between the 40 mm gate and the 120 mm wide gate is refused, and taken when it
  // confirms the last such refusal on its axis (the same way: North +100 and South -100 both say
  // "100 mm further North"). An accepted reading on the axis, or one asking the other way, forgets
  // the refusal; a non-straight wall or another axis does not.
  struct Reading {
    Dir d;
    int32_t offset;
    bool straight;
    bool accepted;
  };
  struct Case {
    const char* what;
    bool confirm;
    std::vector<Reading> readings;
    int32_t yAbove, yBelow;  // the final offset North lies in (yAbove, yBelow)
  };
  const Case cases[] = {
      {"twice the same face", true, {{Dir::North, 100, true, false}, {Dir::North, 95, true, true}}, 80, 100},
      {"from both sides", true, {{Dir::North, 100, true, false}, {Dir::South, -100, true, true}}, 80, 101},
      {"short twice", true, {{Dir::North, -90, true, false}, {Dir::North, -90, true, true}}, -91, -75},
      {"the other way", true, {{Dir::North, 100, true, false}, {Dir::North, -100, true, false}}, -5, 5},
      {"not a straight face", true, {{Dir::North, 100, true, false}, {Dir::North, 100, false, false}}, -5, 5},
      {"beyond the wide gate", true, {{Dir::North, 130, true, false}, {Dir::North, 130, true, false}}, -5, 5},
      {"confirmation off", false, {{Dir::North, 100, true, false}, {Dir::North, 100, true, false}}, -5, 5},
      {"an accepted reading between",
       true,
       {{Dir::North, 100, true, false}, {Dir::North, 3, false, true}, {Dir::North, 100, true, false}},
       -1,
       8},
      {"another axis and a corner between",
       true,
       {{Dir::North, 100, true, false},
        {Dir::East, 100, true, false},
        {Dir::North, 100, false, false},
        {Dir::North, 100, true, true}},
       80,
       101},
  };
  for (const Case& c : cases) {
    PoseNoise noise;
    noise.confirmWide = c.confirm;
    PoseTracker t(noise);
    t.rotated(1571, 1);
    for (int i = 0; i < 3; ++i) t.drove(100, Dir::East);
    for (size_t i = 0; i < c.readings.size(); ++i) {
      const Reading& r = c.readings[i];
      EXPECT_EQ(t.measure(r.d, r.offset, 0, r.straight), r.accepted) << c.what << ", reading " << i;
    }
    EXPECT_GT(t.yMm(), c.yAbove) << c.what;
    EXPECT_LT(t.yMm(), c.yBelow) << c.what;
  }
}

TEST(PoseTracker, RepeatedReadingsConverge) {
  PoseTracker t;
  t.rotated(1571, 1);
  t.drove(1000, Dir::East);
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(t.measure(Dir::South, 12));
  EXPECT_NEAR(t.yMm(), -12, 2);
  EXPECT_LT(t.varianceAlong(Dir::South), 64 / 4);
}

TEST(PoseTracker, AHeadingMeasurementPullsThetaAndTheOffsetItCaused) {
  PoseNoise noise;
  noise.turnMradPerQuarter = 50;
  PoseTracker t(noise);
  t.rotated(1571, 1);  // facing East, heading uncertain (about 50 mrad)
  t.drove(500, Dir::East);
  const int64_t before = t.thetaVariance();
  // The heading was 40 mrad clockwise (to the right, South): 500 mm of driving moved the robot
  // about 20 mm South as well, which the filter infers through the correlation.
  ASSERT_TRUE(t.measureHeading(40, 100));
  EXPECT_GT(t.thetaMrad(), 30);
  EXPECT_LE(t.thetaMrad(), 40);
  EXPECT_LT(t.yMm(), -10);
  EXPECT_LT(t.thetaVariance(), before / 4);
  EXPECT_EQ(t.accepted(), 1u);
}

TEST(PoseTracker, AHeadingFarOutsideItsUncertaintyIsRefused) {
  PoseTracker t;  // exactly on the axis: a few mrad at most after one turn
  t.rotated(1571, 1);
  EXPECT_FALSE(t.measureHeading(300, 25));
  EXPECT_EQ(t.thetaMrad(), 0);  // unchanged
  EXPECT_EQ(t.rejected(), 1u);
}

TEST(PoseTracker, AHandedOverHeadingUncertaintyLetsAHeadingMeasurementCorrectIt) {
  // Handed over by another pilot with sigma 20 mrad: a measured 30 mrad error is believed (mostly).
  PoseTracker handed;
  handed.reset(400);
  EXPECT_EQ(handed.thetaVariance(), 400);
  EXPECT_EQ(handed.xMm(), 0);
  EXPECT_TRUE(handed.measureHeading(30, 100));
  EXPECT_EQ(handed.thetaMrad(), 24);  // 30 * 400 / (400 + 100)
  // Put down on the axis: the heading is known exactly and the same measurement changes nothing.
  PoseTracker placed;
  placed.reset();
  (void)placed.measureHeading(30, 100);
  EXPECT_EQ(placed.thetaMrad(), 0);
}

TEST(PoseTracker, QuarterTurnsAreCountedToTheMicroradian) {
  // 1571 mrad is 0.204 mrad more than a quarter turn: a thousand of them leave 204 mrad.
  PoseTracker t;
  for (int i = 0; i < 1000; ++i) t.rotated(1571, 1);
  EXPECT_NEAR(t.thetaMrad(), 204, 1);
  // Four of 1571 and one of 1570 average 1570.8 mrad: 0.004 mrad too much per turn, 4 mrad after 1000.
  PoseTracker u;
  for (int i = 0; i < 1000; ++i) u.rotated(i % 5 == 4 ? 1570 : 1571, 1);
  EXPECT_NEAR(u.thetaMrad(), 4, 1);
}

}  // namespace
}  // namespace nxtmap
