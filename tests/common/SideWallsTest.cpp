#include "common/motion/SideWalls.hpp"

#include <gtest/gtest.h>

namespace nxtmap {
namespace {

constexpr int32_t kMinBaseMm = 300;

// One leg of a path: turn to `heading` (a quarter turn when it changes), drive `mm`, then read the wall seen
// along `side` in `line` at `rangeMm` (no reading when rangeMm is 0).
struct Leg {
  Dir heading;
  int32_t mm;
  Dir side;
  int16_t line;
  int32_t rangeMm;
};

struct Paired {
  int readings = 0;  // readings that made a pair
  SideSlope last;    // the last pair
};

Paired walk(SideWalls& w, Dir start, std::initializer_list<Leg> legs) {
  Paired out;
  Dir heading = start;
  for (const Leg& leg : legs) {
    if (leg.heading != heading) w.turned();
    heading = leg.heading;
    w.drove(heading, leg.mm, 0);
    if (leg.rangeMm == 0) continue;
    w.tried(leg.side);
    SideSlope s;
    if (w.pair(leg.side, leg.line, leg.rangeMm, kMinBaseMm, s)) {
      ++out.readings;
      out.last = s;
    }
  }
  return out;
}

// 20 mrad of heading error: 600 mm along a wall bring the robot 12 mm nearer it than the wheels tell (it
// believes it drove square).
TEST(SideWalls, ARunAlongAWallShowsTheHeadingError) {
  const struct {
    const char* what;
    Dir heading;
    int32_t mm;
    Dir side;
    int32_t secondRangeMm;
    int32_t errorMrad, baseMm;
  } table[] = {
      // Facing east, clockwise error: towards the south wall on the right, away from the north one on the left.
      {"east, wall on the right", Dir::East, 600, Dir::South, 488, 20, 600},
      {"east, wall on the left", Dir::East, 600, Dir::North, 512, 20, -600},
      {"east, no error", Dir::East, 600, Dir::South, 500, 0, 600},
      {"east, anticlockwise error", Dir::East, 600, Dir::South, 512, -20, 600},
      // Facing west and backing east: a clockwise error (towards north when facing west) backs towards south.
      {"backing, wall on the left", Dir::West, -600, Dir::South, 488, 20, 600},
      {"north, wall on the right", Dir::North, 600, Dir::East, 488, 20, 600},
  };
  for (const auto& row : table) {
    SideWalls w;
    const Paired p = walk(w, row.heading, {{row.heading, 0, row.side, 7, 500}, {row.heading, row.mm, row.side, 7, row.secondRangeMm}});
    ASSERT_EQ(p.readings, 1) << row.what;
    EXPECT_EQ(p.last.errorMrad, row.errorMrad) << row.what;
    EXPECT_EQ(p.last.baseMm, row.baseMm) << row.what;
    EXPECT_EQ(p.last.turns, 0) << row.what;
    EXPECT_EQ(p.last.acrossPathMm, 0) << row.what;
  }
}

TEST(SideWalls, AZigzagReadsTheSameWallAcrossItsTurns) {
  // East, north, east: the south wall read before and after; the robot came 200 mm further from it by the
  // wheels and 8 mm less than that by the ranges (20 mrad over the 400 mm driven east).
  SideWalls w;
  const Paired p = walk(w, Dir::East,
                        {{Dir::East, 0, Dir::South, 3, 500},
                         {Dir::East, 200, Dir::South, 3, 0},
                         {Dir::North, 200, Dir::South, 3, 0},
                         {Dir::East, 200, Dir::South, 3, 692}});
  ASSERT_EQ(p.readings, 1);
  EXPECT_EQ(p.last.errorMrad, 20);
  EXPECT_EQ(p.last.baseMm, 400);
  EXPECT_EQ(p.last.turns, 2);
  EXPECT_EQ(p.last.acrossPathMm, 200);  // the drive north: its slip is part of the pair's error
}

TEST(SideWalls, ATooShortBaseKeepsTheOlderReading) {
  SideWalls w;
  const Paired p = walk(w, Dir::East,
                        {{Dir::East, 0, Dir::South, 3, 500},
                         {Dir::East, 200, Dir::South, 3, 497},    // 200 mm: too near, not taken
                         {Dir::East, 400, Dir::South, 3, 488}});  // 600 mm from the first
  ASSERT_EQ(p.readings, 1);
  EXPECT_EQ(p.last.baseMm, 600);
  EXPECT_EQ(p.last.errorMrad, 20);
}

TEST(SideWalls, EachSideRemembersItsLastTwoWalls) {
  // Walls in lines 3, 4 and 5 beside the path: the third takes the place of the first.
  SideWalls w;
  const Paired p = walk(w, Dir::East,
                        {{Dir::East, 0, Dir::South, 3, 500},
                         {Dir::East, 0, Dir::South, 4, 300},
                         {Dir::North, 0, Dir::West, 9, 400},  // another side: its own marks
                         {Dir::East, 0, Dir::South, 5, 700},
                         {Dir::East, 600, Dir::South, 4, 300},
                         {Dir::East, 0, Dir::South, 5, 700},
                         {Dir::East, 600, Dir::South, 3, 500}});
  EXPECT_EQ(p.readings, 2);  // lines 4 and 5 paired; line 3 was forgotten
  SideWalls again;
  const Paired q = walk(again, Dir::East,
                        {{Dir::East, 0, Dir::South, 3, 500},
                         {Dir::East, 0, Dir::South, 4, 300},
                         {Dir::East, 600, Dir::South, 3, 500}});
  EXPECT_EQ(q.readings, 1);  // two walls: both kept
}

TEST(SideWalls, PositionsWrapWithoutBreakingAPair) {
  // 32.4 m east and then 600 mm more: past 2^15 mm, where the positions wrap.
  SideWalls w;
  for (int i = 0; i < 162; ++i) w.drove(Dir::East, 200, 0);
  SideSlope s;
  EXPECT_FALSE(w.pair(Dir::South, 3, 500, kMinBaseMm, s));
  w.drove(Dir::East, 600, 0);
  ASSERT_TRUE(w.pair(Dir::South, 3, 488, kMinBaseMm, s));
  EXPECT_EQ(s.baseMm, 600);
  EXPECT_EQ(s.errorMrad, 20);
}

TEST(SideWalls, TheBelievedHeadingIsPartOfWhatTheWheelsTell) {
  // The robot believes it is 20 mrad clockwise off east, and it is: it came 12 mm nearer the south wall in
  // 600 mm, as the wheels (with that heading) tell: no error is left.
  SideWalls w;
  SideSlope s;
  EXPECT_FALSE(w.pair(Dir::South, 3, 500, kMinBaseMm, s));
  w.drove(Dir::East, 600, 20);
  ASSERT_TRUE(w.pair(Dir::South, 3, 488, kMinBaseMm, s));
  EXPECT_EQ(s.errorMrad, 0);
}

TEST(SideWalls, TheReadingPolicyKnowsTheRun) {
  SideWalls w;
  EXPECT_FALSE(w.held(Dir::South));
  EXPECT_FALSE(w.triedInRun(Dir::South));
  w.tried(Dir::South);
  SideSlope s;
  (void)w.pair(Dir::South, 3, 500, kMinBaseMm, s);
  EXPECT_TRUE(w.held(Dir::South));
  EXPECT_TRUE(w.triedInRun(Dir::South));
  w.drove(Dir::East, 350, 0);
  EXPECT_EQ(w.sinceMm(Dir::South), 350);
  w.turned();  // a new run: the wall is still remembered, but not read in this run
  EXPECT_FALSE(w.held(Dir::South));
  EXPECT_FALSE(w.triedInRun(Dir::South));
  w.tried(Dir::South);
  w.drove(Dir::East, -150, 0);
  EXPECT_EQ(w.sinceMm(Dir::South), 150);  // from where it was last tried
  w.clear();
  w.drove(Dir::East, 600, 0);
  EXPECT_FALSE(w.pair(Dir::South, 3, 488, kMinBaseMm, s));  // cleared: nothing to pair with
}

}  // namespace
}  // namespace nxtmap
