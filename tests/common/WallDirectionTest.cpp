// WallDirection against sweeps computed here from geometry: a sonar with a cone (the nearest wall point
// within +-b of the axis, whole cm) turned on the spot in a rectangular room set at a known angle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/sensing/WallDirection.hpp"

namespace nxtmap {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Room {
  double west = 80, east = 120, south = 70, north = 90;  // wall distances from the robot's centre, cm
  double turnedDeg = 0;                                  // the room turned clockwise against the start heading
};

// Distance from (x, y) along compass angle deg (0 = north, clockwise) to the rectangle's walls (room frame).
double rayToWalls(const Room& r, double x, double y, double deg) {
  const double dx = std::sin(deg * kPi / 180), dy = std::cos(deg * kPi / 180);
  double best = 1e9;
  if (dx > 1e-9) best = std::min(best, (r.east - x) / dx);
  if (dx < -1e-9) best = std::min(best, (-r.west - x) / dx);
  if (dy > 1e-9) best = std::min(best, (r.north - y) / dy);
  if (dy < -1e-9) best = std::min(best, (-r.south - y) / dy);
  return best;
}

// One reading: the sensor `mountCm` out along its axis, facing `facingDeg` (robot frame); cone half-angle b.
int16_t reading(const Room& r, double facingDeg, double mountCm, double coneDeg) {
  const double inRoom = facingDeg - r.turnedDeg;  // the ray's compass angle in the room's frame
  const double fx = mountCm * std::sin(inRoom * kPi / 180), fy = mountCm * std::cos(inRoom * kPi / 180);
  double best = 1e9;
  for (double c = -coneDeg; c <= coneDeg + 1e-9; c += 0.25) best = std::min(best, rayToWalls(r, fx, fy, inRoom + c));
  return best > 255 ? 0 : static_cast<int16_t>(std::lround(best));
}

// A sweep of +-90 deg in 5 deg steps (as the pilot turns it); `errorCm` adds a fixed error per pose and
// sensor (-1, 0, +1 cm, repeatable, as the NXT sensor's).
WallDirection sweep(const Room& r, double mountCm, double coneDeg, bool errorCm = false) {
  WallDirection w;
  for (int k = 0; k <= 36; ++k) {
    const int32_t mrad = -1571 + 87 * k;
    w.addHeading(mrad);
    for (int s = 0; s < kSensorCount; ++s) {
      int16_t cm = reading(r, mrad * 0.18 / kPi + 90.0 * s, mountCm, coneDeg);
      if (errorCm && cm > 0) cm = static_cast<int16_t>(cm + ((k * 7 + s * 3) % 3) - 1);
      w.addReading(static_cast<Sensor>(s), cm);
    }
  }
  return w;
}

struct Row {
  double turnedDeg, mountCm, coneDeg;
  bool error;
  double expectDeg;  // the walls' normals modulo 90, in [-45, 45)
  double withinDeg;
};

TEST(WallDirection, FindsTheWallsOfARectangularRoomTurnedAnyWay) {
  const Row rows[] = {
      {0, 0, 12, false, 0, 1.0},   {3, 0, 12, false, 3, 1.0},    {10, 0, 12, false, 10, 1.0},
      {44, 0, 12, false, 44, 1.0}, {-7, 6, 15, false, -7, 1.0},  {3, 6, 10, true, 3, 1.5},
      {10, 6, 15, true, 10, 1.5},  {-25, 6, 12, true, -25, 1.5}, {44, 6, 12, true, 44, 1.5},
      {60, 6, 12, true, -30, 1.5}, {-44, 0, 12, true, -44, 1.5}, {90, 0, 12, false, 0, 1.0},
  };
  for (const Row& row : rows) {
    Room room;
    room.turnedDeg = row.turnedDeg;
    const WallDirectionEstimate e = sweep(room, row.mountCm, row.coneDeg, row.error).estimate();
    ASSERT_TRUE(e.found) << "turned " << row.turnedDeg;
    double got = e.mrad * 0.18 / kPi, diff = got - row.expectDeg;
    while (diff > 45) diff -= 90;
    while (diff < -45) diff += 90;
    EXPECT_LE(std::fabs(diff), row.withinDeg) << "turned " << row.turnedDeg << " got " << got;
    EXPECT_GE(e.agreeing, 3) << "turned " << row.turnedDeg << ": each wall in range should agree";
  }
}

TEST(WallDirection, NoWallInRangeIsNoEstimate) {
  Room far;
  far.west = far.east = far.north = far.south = 400;  // every echo beyond the sensor's 255 cm
  const WallDirectionEstimate e = sweep(far, 6, 12).estimate();
  EXPECT_FALSE(e.found);
  EXPECT_EQ(e.dips, 0);
  EXPECT_EQ(e.mrad, 0);
}

TEST(WallDirection, ARoundRoomHasNoWallDirection) {
  WallDirection w;
  for (int k = 0; k <= 36; ++k) {
    w.addHeading(-1571 + 87 * k);
    for (int s = 0; s < kSensorCount; ++s) w.addReading(static_cast<Sensor>(s), 60);
  }
  EXPECT_FALSE(w.estimate().found);
}

TEST(WallDirection, OneWallInRangeIsEnough) {
  Room one;
  one.west = one.east = one.south = 400;
  one.north = 50;
  one.turnedDeg = 8;
  const WallDirectionEstimate e = sweep(one, 6, 12).estimate();
  ASSERT_TRUE(e.found);
  EXPECT_EQ(e.dips, 1);
  EXPECT_NEAR(e.mrad * 0.18 / kPi, 8.0, 1.0);
}

TEST(WallDirection, HandComputedDipCentreAndObjectEdge) {
  // Front sensor, headings -435..435 mrad in steps of 87. Floor 50 cm, so the level is 50 + 50 / 10 = 55.
  const int16_t wall[] = {60, 54, 51, 50, 50, 50, 50, 50, 51, 54, 60};
  WallDirection w;
  for (int k = 0; k < 11; ++k) {
    w.addHeading(-435 + 87 * k);
    w.addReading(Sensor::Front, wall[k]);
  }
  WallDirection::Dip d[4];
  ASSERT_EQ(w.dips(d, 4), 1);
  // Left flank: inside at -348 (54), outside at -435 (60): crossing at -348 - 87 * 1 / 6 = -362 (whole mrad).
  // Right flank likewise at +362: centre 0, width 724.
  EXPECT_EQ(d[0].centreMrad, 0);
  EXPECT_EQ(d[0].widthMrad, 724);
  EXPECT_EQ(d[0].floorCm, 50);

  // The same floor, but past its right flank the echo jumps above 55 + 50 / 16 + 4 = 62 cm (a wall's flank rises
  // about 5 % of its floor per 5 degree step where it passes the level): an object's edge. 62 is still a wall's.
  struct Edge {
    int16_t pastCm;
    int dips;
  };
  // (The floor one step wider than above: the right flank's crossing comes early, and the dip stays wider than
  // minDipMrad().)
  for (const Edge edge : {Edge{130, 0}, Edge{63, 0}, Edge{62, 1}, Edge{58, 1}}) {
    const int16_t object[] = {60, 54, 51, 50, 50, 50, 50, 50, 50, 51, edge.pastCm, edge.pastCm};
    WallDirection o;
    for (int k = 0; k < 12; ++k) {
      o.addHeading(-435 + 87 * k);
      o.addReading(Sensor::Front, object[k]);
    }
    EXPECT_EQ(o.dips(d, 4), edge.dips) << "past the right flank " << edge.pastCm << " cm";
  }
}

TEST(WallDirection, ALoneWildEchoIsReadAsItsNearerNeighbour) {
  // The hand-computed dip above (floor 50, level 55, centre 0, width 724) with one reading replaced. A reading
  // more than kLoneDropCm (3) + a tenth of the nearer neighbour below both neighbours is a wild echo and read as
  // that neighbour: at heading 2 the neighbours are 54 and 50, so 41 (41 + 3 + 5 < 50) is wild and the dip is as
  // clean; 42 is an echo (a thing 42 cm off), whose edge jumps to 54: no wall. Two in a row, or one beside a
  // missing echo, are echoes too.
  struct Case {
    int at;
    int16_t cm;
    int at2;  // a second reading set to cm2 (-1: none)
    int16_t cm2;
    int dips;
  };
  for (const Case c : {Case{2, 41, -1, 0, 1}, Case{5, 20, -1, 0, 1}, Case{8, 30, -1, 0, 1}, Case{2, 42, -1, 0, 0},
                       Case{4, 30, 5, 30, 0}, Case{2, 30, 3, 0, 0}}) {
    int16_t cm[] = {60, 54, 51, 50, 50, 50, 50, 50, 51, 54, 60};
    cm[c.at] = c.cm;
    if (c.at2 >= 0) cm[c.at2] = c.cm2;
    WallDirection w;
    for (int k = 0; k < 11; ++k) {
      w.addHeading(-435 + 87 * k);
      w.addReading(Sensor::Front, cm[k]);
    }
    WallDirection::Dip d[4];
    ASSERT_EQ(w.dips(d, 4), c.dips) << c.cm << " cm at heading " << c.at;
    if (c.dips == 1) {
      EXPECT_EQ(d[0].centreMrad, 0) << c.cm << " cm at heading " << c.at;
      EXPECT_EQ(d[0].widthMrad, 724) << c.cm << " cm at heading " << c.at;
    }
  }
}

TEST(WallDirection, AFlankThatRunsOffTheSweepAmongMissingEchoesIsCutOff) {
  // A floor of 107 cm (level 117) whose left flank has not risen where the sweep ends. Two missing echoes in a
  // row end a flank as risen (specular loss on a wall's flank); one alone is passed over (a lost ping), so one
  // on the sweep's last heading says nothing of a rise: the floor may go on past the end, and the dip's centre is
  // not known. (Seen on the brick under nxt: such a dip, 12 degrees off the walls, outvoted a wall's clean
  // one, and the robot mapped as set down, 9 degrees off.) The right flank rises
  // through the level at 120 cm, far enough along for the dip to be wide enough.
  struct Case {
    int16_t first, second;  // the sweep's first two readings (0: no echo)
    int dips;
  };
  // Risen before the sweep's end (120 or 125 cm) or lost for two headings: a dip; one missing echo (passed
  // over), then the end: cut off.
  for (const Case c : {Case{0, 110, 0}, Case{0, 0, 1}, Case{110, 0, 0}, Case{120, 110, 1}, Case{0, 125, 1}}) {
    const int16_t cm[] = {c.first, c.second, 108, 107, 108, 108, 109, 110, 110, 112, 116, 120, 126};
    WallDirection w;
    for (int k = 0; k < 13; ++k) {
      w.addHeading(-1571 + 87 * k);
      w.addReading(Sensor::Left, cm[k]);
    }
    WallDirection::Dip d[4];
    EXPECT_EQ(w.dips(d, 4), c.dips) << "sweep starting " << c.first << ", " << c.second << " cm";
  }
}

TEST(WallDirection, OneWallSeenByTwoSensorsIsOneWall) {
  // One wall 60 cm north, turned 42 degrees: the front sensor faces its normal at +42 degrees of the sweep, the
  // right one at -48. Two dips a quarter turn apart agree modulo a quarter turn, but they are one wall: one vote.
  Room one;
  one.west = one.east = one.south = 400;
  one.north = 60;
  one.turnedDeg = 42;
  const WallDirection w = sweep(one, 6, 12);
  WallDirection::Dip d[4];
  ASSERT_EQ(w.dips(d, 4), 2);
  EXPECT_EQ(d[0].sensor, Sensor::Front);
  EXPECT_EQ(d[1].sensor, Sensor::Right);
  const WallDirectionEstimate e = w.estimate();
  EXPECT_EQ(e.dips, 1);
  EXPECT_EQ(e.agreeing, 1);
  ASSERT_TRUE(e.found) << "a wall alone, wide and clean, still names the walls";
  EXPECT_NEAR(e.mrad * 0.18 / kPi, 42.0, 1.5);

  // A post 100 cm away, 20 cm wide, seen by the front sensor at +25 degrees and by the right one at -65: its
  // nearest point stays in the 12 degree cone for 24 degrees, then the echo jumps to the far wall or is lost.
  // Once two dips agreed (and named walls 25 degrees off); now it is one narrow thing, no wall.
  WallDirection post;
  for (int k = 0; k <= 36; ++k) {
    const int32_t mrad = -1571 + 87 * k;
    post.addHeading(mrad);
    for (int s = 0; s < 2; ++s) {
      const double off = mrad * 0.18 / kPi + 90.0 * s - 25.0;  // degrees from the post's bearing
      post.addReading(static_cast<Sensor>(s), std::fabs(off) <= 17.5 ? 100 : (std::fabs(off) <= 22.5 ? 104 : 0));
    }
  }
  // The right sensor's view of it begins one heading after the sweep does (a lone missing echo first): cut off.
  ASSERT_EQ(post.dips(d, 4), 1);
  EXPECT_EQ(d[0].sensor, Sensor::Front);
  EXPECT_EQ(post.estimate().dips, 1);
  EXPECT_FALSE(post.estimate().found);
}

TEST(WallDirection, HeadingsMustIncreaseAndFitTheCapacity) {
  WallDirection w;
  EXPECT_TRUE(w.addHeading(0));
  EXPECT_FALSE(w.addHeading(0));
  EXPECT_FALSE(w.addHeading(-10));
  for (int k = 1; k < WallDirection::kMaxSteps; ++k) EXPECT_TRUE(w.addHeading(10 * k));
  EXPECT_FALSE(w.addHeading(100000));
  EXPECT_EQ(w.steps(), WallDirection::kMaxSteps);
}

}  // namespace
}  // namespace nxtmap
