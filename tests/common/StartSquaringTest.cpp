// StartSquaring and WallDirection's last resort, events in and actions out: a sweep whose two wall dips disagree
// (two walls 6 degrees apart, or two dips each off by a few degrees) names no walls while an approach may still
// find better; on the last sweep it takes the widest wall dip rather than leave the robot as it was set down.
// And whether a sweep heard anything at all.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "common/motion/StartSquaring.hpp"
#include "common/sensing/WallDirection.hpp"
#include "tests/common/SweptWalls.hpp"

namespace nxtmap {
namespace {

using sweptwalls::kPi;
using sweptwalls::TwoWalls;

WallDirection sweep(const TwoWalls& room) {
  WallDirection w;
  for (int k = 0; k <= 36; ++k) {
    const int32_t mrad = -1571 + 87 * k;
    w.addHeading(mrad);
    for (int s = 0; s < kSensorCount; ++s)
      w.addReading(static_cast<Sensor>(s), room.read(static_cast<Sensor>(s), mrad));
  }
  return w;
}

TEST(WallDirectionWidest, TwoDisagreeingWallDipsNameNoWallsButTheWidestIsTheLastResort) {
  const WallDirection w = sweep(TwoWalls{});
  WallDirection::Dip d[4];
  ASSERT_EQ(w.dips(d, 4), 2);
  EXPECT_TRUE(d[0].clean && d[1].clean);
  EXPECT_GT(d[0].widthMrad, d[1].widthMrad) << "the near wall's dip is the wider (3 cm of 25 is more than 10 %)";
  const WallDirectionEstimate strict = w.estimate();
  EXPECT_FALSE(strict.found) << "6 degrees apart: more than kAgreeMrad";
  EXPECT_EQ(strict.dips, 2);
  const WallDirectionEstimate widest = w.widestWall();
  ASSERT_TRUE(widest.found);
  EXPECT_EQ(widest.agreeing, 1);
  EXPECT_NEAR(widest.mrad * 0.18 / kPi, 3.0, 1.0) << "the front's wall";
}

TEST(WallDirectionWidest, NoDipWideAndCleanEnoughIsNoWall) {
  // A post: a narrow dip only (under lastResortDipMrad()), and nothing else.
  WallDirection w;
  for (int k = 0; k <= 36; ++k) {
    const int32_t mrad = -1571 + 87 * k;
    w.addHeading(mrad);
    const double deg = mrad * 0.18 / kPi;
    w.addReading(Sensor::Front, std::fabs(deg - 20.0) <= 17.5 ? 100 : (std::fabs(deg - 20.0) <= 22.5 ? 104 : 0));
  }
  EXPECT_FALSE(w.estimate().found);
  EXPECT_FALSE(w.widestWall().found);
}

// One clean dip seen by `s`: floor 50 cm (level 55), 870 mrad (50 degrees) wide, centred on the sweep's zero.
void addFiftyDegreeDip(WallDirection& w, Sensor s) {
  const int16_t cm[] = {60, 55, 54, 52, 50, 50, 50, 50, 50, 52, 54, 55, 60};
  for (int k = 0; k < 13; ++k) {
    w.addHeading(-522 + 87 * k);
    w.addReading(s, cm[k]);
  }
}

TEST(WallDirectionWidest, ADipAloneMustBeWiderThanTheLastResortAsks) {
  // A 50 degree dip alone names no walls (loneDipMrad(): dips that narrow were 5 degrees or more off the walls one
  // time in five); as the last resort it does.
  WallDirection w;
  addFiftyDegreeDip(w, Sensor::Left);
  WallDirection::Dip d[2];
  ASSERT_EQ(w.dips(d, 2), 1);
  ASSERT_TRUE(d[0].clean);
  ASSERT_GT(d[0].widthMrad, w.lastResortDipMrad());
  ASSERT_LT(d[0].widthMrad, w.loneDipMrad());
  EXPECT_FALSE(w.estimate().found);
  const WallDirectionEstimate last = w.widestWall();
  ASSERT_TRUE(last.found);
  EXPECT_EQ(last.mrad, 0);
}

TEST(WallDirectionWidest, HowWideADipMustBeFollowsTheSonarsBeam) {
  struct Row {
    int32_t coneMrad;  // the sonar's widest beam half-angle
    int32_t minDip, lone, lastResort;
    bool fiftyDegreesAlone;  // a clean 50 degree dip alone names the walls
  };
  const Row rows[] = {
      {0, 524, 785, 785, true},     // one ray: the floors (30 and 45 deg)
      {87, 524, 785, 785, true},    // 5 deg (`typical`)
      {262, 700, 900, 785, false},  // the NXT's 15 deg
      {349, 874, 1074, 959, false},
  };
  for (const Row& row : rows) {
    WallDirection w(row.coneMrad);
    EXPECT_EQ(w.minDipMrad(), row.minDip) << row.coneMrad;
    EXPECT_EQ(w.loneDipMrad(), row.lone) << row.coneMrad;
    EXPECT_EQ(w.lastResortDipMrad(), row.lastResort) << row.coneMrad;
    addFiftyDegreeDip(w, Sensor::Front);
    EXPECT_EQ(w.estimate().found, row.fiftyDegreesAlone) << row.coneMrad;
  }
}

// Runs one sweep of StartSquaring in `room`, the wheels turning as told; returns its result.
WallDirectionEstimate runSweep(const TwoWalls& room, int approachesLeft, int32_t& endHeadingMrad) {
  StartSquaring squaring;
  int32_t heading = 0;
  DriveAction a = squaring.begin(approachesLeft);
  for (int i = 0; i < 1000 && !squaring.finished(); ++i) {
    if (a.kind == DriveAction::Kind::Rotate) {
      heading += a.value;
      a = squaring.step(DriveEvent::rotatedBy(a.value));
    } else {
      EXPECT_EQ(a.kind, DriveAction::Kind::Read);
      RangeReading r;
      r.cm = room.read(a.sensor, heading);
      r.status = r.cm > 0 ? RangeStatus::Good : RangeStatus::NoEcho;
      r.samples = 1;
      a = squaring.step(DriveEvent::range(a.sensor, r));
    }
  }
  EXPECT_TRUE(squaring.finished());
  endHeadingMrad = heading;
  return squaring.result();
}

TEST(StartSquaring, TheLastSweepTakesTheWidestWallDipAnEarlierOneLeavesItToTheApproach) {
  struct Row {
    double rightCm;      // the far wall: beyond 70 cm an approach can drive towards it
    int approachesLeft;  // the pilot's (-1: a calibration's sweep, never)
    bool found;
  };
  const Row rows[] = {
      {80, 1, false},  // an approach follows: it may find two walls that agree
      {80, 0, true},   // none left: the widest dip
      {40, 2, true},   // nothing 70 cm away to approach: this is the last sweep
      {80, -1, false}, {40, -1, false},
  };
  for (const Row& row : rows) {
    TwoWalls room;
    room.rightCm = row.rightCm;
    int32_t heading = 0;
    const WallDirectionEstimate e = runSweep(room, row.approachesLeft, heading);
    EXPECT_EQ(e.found, row.found) << row.rightCm << " cm, approaches left " << row.approachesLeft;
    EXPECT_EQ(e.dips, 2);
    if (row.found) {
      EXPECT_NEAR(heading * 0.18 / kPi, 3.0, 1.0) << "turned onto the front's wall";
    } else {
      EXPECT_EQ(heading, 0) << "back where it was set down";
    }
  }
}

// One sweep in which the back sensor alone, facing the sweep's zero, reads `status` (at `cm`); every other
// reading has no echo. Whether the sweep heard nothing (StartSquaring::heardNothing: the pilot may drive blind).
bool heardNothingWhenTheBackReads(RangeStatus status, int16_t cm) {
  StartSquaring squaring;
  int32_t heading = 0;
  DriveAction a = squaring.begin(2);
  for (int i = 0; i < 1000 && !squaring.finished(); ++i) {
    if (a.kind == DriveAction::Kind::Rotate) {
      heading += a.value;
      a = squaring.step(DriveEvent::rotatedBy(a.value));
      continue;
    }
    RangeReading r;
    const bool back = a.sensor == Sensor::Back && heading > -50 && heading < 50;
    r.status = back ? status : RangeStatus::NoEcho;
    r.cm = back ? cm : 255;
    r.samples = 1;
    a = squaring.step(DriveEvent::range(a.sensor, r));
  }
  EXPECT_TRUE(squaring.finished());
  EXPECT_FALSE(squaring.result().found);
  return squaring.heardNothing();
}

TEST(StartSquaring, ASweepHearsNothingOnlyWhenNoReadingHadAnEcho) {
  struct Row {
    RangeStatus status;
    int16_t cm;
    bool heardNothing;
  };
  const Row rows[] = {
      {RangeStatus::NoEcho, 255, true},       // nothing anywhere: the middle of a hall
      {RangeStatus::Inconsistent, 90, true},  // samples that disagree say nothing
      {RangeStatus::Good, 90, false},         // one echo in range
      {RangeStatus::TooFar, 200, false},      // one beyond the trusted range the samples agree on
      {RangeStatus::TooNear, 3, false},       // something at the robot's side: no blind drive
  };
  for (const Row& row : rows) {
    EXPECT_EQ(heardNothingWhenTheBackReads(row.status, row.cm), row.heardNothing)
        << static_cast<int>(row.status) << " at " << row.cm << " cm";
  }
}

}  // namespace
}  // namespace nxtmap
