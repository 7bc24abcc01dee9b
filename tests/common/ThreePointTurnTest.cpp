// The three-point turn on its own: how far it drives out for a stall at each angle (hand-computed from the
// brick's body, 16 x 18 cm), how far its cell lets it, and each way its steps can go. And the integer sine and
// cosine it rests on.
#include <gtest/gtest.h>

#include <cmath>

#include "common/math/IntTrig.hpp"
#include "common/motion/ThreePointTurn.hpp"

namespace nxtmap {
namespace {

TEST(IntTrig, SineAndCosineInPerMilleWithinOneAndATenth) {
  for (int32_t a = -1600; a <= 1600; a += 7) {
    EXPECT_NEAR(sinPerMille(a), 1000.0 * std::sin(a / 1000.0), 1.1) << a;
    EXPECT_NEAR(cosPerMille(a), 1000.0 * std::cos(a / 1000.0), 1.1) << a;
  }
}

TEST(ThreePointTurn, TheDriveOutClearsTheCornersAtTheAngleTheTurnStalled) {
  // now = (80 cos a + 90 sin a) / 1000 (the corners' reach), need = 120 - now + 5, out = need / sin a, 5..110.
  struct Row {
    int32_t stalledMrad, outMm;
  } rows[] = {
      {0, 0},      // stalled at once: turned back
      {149, 0},    // below 150 mrad: turned back
      {150, 110},  // now 92, need 33, 33 / 0.149 = 221: at most 110
      {300, 77},   // cos 955, sin 295: now 102, need 23
      {-300, 77},  // anticlockwise alike
      {500, 25},   // cos 877, sin 479: now 113, need 12
      {800, 6},    // cos 696, sin 717: now 120 (the corners' farthest), need 5
      {1200, 13},  // cos 362, sin 932: now 112, need 13
      {1201, 0},   // nearly turned: turned back
  };
  for (const Row& r : rows) EXPECT_EQ(ThreePointTurn::outMm(r.stalledMrad), r.outMm) << r.stalledMrad;
}

TEST(ThreePointTurn, TheDriveOutKeepsTheRobotInItsCell) {
  // 300 mrad wants 77 mm out, 77 * 0.955 = 74 mm along the heading: more than the 70 mm allowed from the centre.
  struct Row {
    int direction;
    int32_t offsetMm;  // ahead of the cell's centre
    int32_t driveMm;   // 0: not tried
  } rows[] = {
      {+1, 0, 73},    // 70 / 0.955
      {-1, 0, -73},   // backward alike
      {+1, 30, 41},   // 40 mm of room ahead
      {-1, 30, -77},  // behind it has 100 mm: all it wants
      {+1, 70, 0},    // no room: turned back
      {+1, 66, 0},    // 4 mm of room: under the 5 mm worth a drive
  };
  for (const Row& r : rows) {
    ThreePointTurn t;
    const DriveAction a = t.begin(300, 1271, r.direction, r.offsetMm);
    if (r.driveMm == 0) {
      EXPECT_EQ(a.kind, DriveAction::Kind::Done) << r.offsetMm;
      EXPECT_EQ(t.partialMrad(), 300);
      EXPECT_FALSE(t.made());
      continue;
    }
    EXPECT_EQ(a.kind, DriveAction::Kind::Drive) << r.offsetMm;
    EXPECT_EQ(a.value, r.driveMm) << r.direction << " " << r.offsetMm;
  }
}

TEST(ThreePointTurn, OutThenTheRestMakesTheTurn) {
  ThreePointTurn t;
  DriveAction a = t.begin(500, 1071, +1, 0);
  ASSERT_EQ(a.kind, DriveAction::Kind::Drive);
  int32_t drove = 0;
  a = t.step(DriveEvent::drivenBy(24), 100, drove);  // the encoders' 24 mm, not the 25 asked
  EXPECT_EQ(drove, 24);
  EXPECT_EQ(t.partialMrad(), 500);  // driven at the partial heading
  ASSERT_EQ(a.kind, DriveAction::Kind::Rotate);
  EXPECT_EQ(a.value, 1071);
  a = t.step(DriveEvent::rotatedBy(1060), 100, drove);  // 11 short: within the stall limit
  EXPECT_EQ(a.kind, DriveAction::Kind::Done);
  EXPECT_EQ(drove, 0);
  EXPECT_TRUE(t.made());
  EXPECT_EQ(t.partialMrad(), 1560);
}

TEST(ThreePointTurn, ARestThatStallsTooTurnsBackAndDrivesBackIn) {
  ThreePointTurn t;
  DriveAction a = t.begin(500, 1071, -1, 0);
  ASSERT_EQ(a.value, -25);
  int32_t drove = 0;
  a = t.step(DriveEvent::drivenBy(-25), 100, drove);
  a = t.step(DriveEvent::rotatedBy(400), 100, drove);  // stalled again, 671 short
  ASSERT_EQ(a.kind, DriveAction::Kind::Rotate);
  EXPECT_EQ(a.value, -400);  // back to the heading it drove out at
  a = t.step(DriveEvent::rotatedBy(-395), 100, drove);
  ASSERT_EQ(a.kind, DriveAction::Kind::Drive);
  EXPECT_EQ(a.value, 25);
  EXPECT_EQ(t.partialMrad(), 505);
  a = t.step(DriveEvent::drivenBy(25), 100, drove);
  EXPECT_EQ(a.kind, DriveAction::Kind::Done);
  EXPECT_FALSE(t.made());
  EXPECT_EQ(drove, 25);  // back in, at the heading it stands turned
  EXPECT_EQ(t.partialMrad(), 505);
}

TEST(ThreePointTurn, ABlockedDriveMovesNothing) {
  // The drive out blocked: given up where the turn stalled.
  ThreePointTurn t;
  t.begin(500, 1071, +1, 0);
  int32_t drove = -1;
  EXPECT_EQ(t.step(DriveEvent::driven(true), 100, drove).kind, DriveAction::Kind::Done);
  EXPECT_EQ(drove, 0);
  EXPECT_FALSE(t.made());
  EXPECT_EQ(t.partialMrad(), 500);
  // The drive back in blocked: given up out where it is (the tracker has the drive out already).
  t.begin(500, 1071, +1, 0);
  t.step(DriveEvent::drivenBy(25), 100, drove);
  t.step(DriveEvent::rotatedBy(0), 100, drove);
  t.step(DriveEvent::rotatedBy(0), 100, drove);
  EXPECT_EQ(t.step(DriveEvent::driven(true), 100, drove).kind, DriveAction::Kind::Done);
  EXPECT_EQ(drove, 0);
  EXPECT_FALSE(t.made());
}

}  // namespace
}  // namespace nxtmap
