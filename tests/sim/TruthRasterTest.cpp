// The truth on the robot's grid by the safe rule (rasterizeScene): rooms on the grid and turned, and the even-odd
// rule with open walls and discs.
#include "host/sim/TruthRaster.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tests/sim/RasterRows.hpp"

namespace nxtmap::sim {
namespace {

using test::box;
using test::joined;
using test::rowsOf;

GridFrame frameAt(double x, double y, double headingDeg = 0.0, double cellCm = 10.0) {
  GridFrame f;
  f.originCm = Vec2(x, y);
  f.headingDeg = headingDeg;
  f.cellCm = cellCm;
  return f;
}

// A 60 x 40 cm room (a ring on the borders of a 6 x 4 grid of 10 cm cells) with one extra element.
struct RoomCase {
  const char* label;
  std::vector<Edge> walls;
  std::vector<Ring> rings;
  std::vector<Disc> discs;
  std::vector<std::string> expected;  // '#' blocked
};

TEST(TruthRaster, SafeRuleInARoomOnTheGrid) {
  const std::vector<RoomCase> cases = {
      {"empty room: its outline lies on the border cells' outer sides",
       {},
       {},
       {},
       {"......", "......", "......", "......"}},
      {"thin wall a quarter cell past a border blocks the column it runs in",
       {Edge{Vec2(32.5, 0), Vec2(32.5, 40)}},
       {},
       {},
       {"...#..", "...#..", "...#..", "...#.."}},
      {"thin wall on a column border blocks neither side",
       {Edge{Vec2(30, 0), Vec2(30, 40)}},
       {},
       {},
       {"......", "......", "......", "......"}},
      {"thin wall on a row border blocks neither side",
       {Edge{Vec2(0, 20), Vec2(60, 20)}},
       {},
       {},
       {"......", "......", "......", "......"}},
      {"wall ending on row borders blocks only the cell between",
       {Edge{Vec2(32.5, 10), Vec2(32.5, 20)}},
       {},
       {},
       {"......", "...#..", "......", "......"}},
      {"one-cell-thick block a quarter cell off the grid blocks both cells it touches",
       {},
       {box(22.5, 10, 32.5, 30)},
       {},
       {"......", "..##..", "..##..", "......"}},
      {"diagonal through a corner blocks only the cells it crosses",
       {Edge{Vec2(10, 10), Vec2(30, 30)}},
       {},
       {},
       {"......", ".#....", "..#...", "......"}},
      {"disc of 1.25 cm at a cell centre blocks exactly its cell",
       {},
       {},
       {Disc{Vec2(35, 25), 1.25}},
       {"......", "......", "...#..", "......"}},
      {"disc of 1.25 cm on a column border blocks both cells",
       {},
       {},
       {Disc{Vec2(40, 25), 1.25}},
       {"......", "......", "...##.", "......"}},
      {"disc of 1.25 cm on a corner blocks the four cells",
       {},
       {},
       {Disc{Vec2(40, 30), 1.25}},
       {"......", "......", "...##.", "...##."}},
      {"disc touching a border from inside blocks only its cell",
       {},
       {},
       {Disc{Vec2(35, 25), 5.0}},
       {"......", "......", "...#..", "......"}},
  };
  for (const RoomCase& c : cases) {
    Scene scene;
    scene.addRing(box(0, 0, 60, 40));
    for (const Edge& w : c.walls) scene.addWall(w);
    for (const Ring& r : c.rings) scene.addRing(r);
    for (const Disc& d : c.discs) scene.addDisc(d);
    scene.finish();
    const World w = rasterizeScene(scene, frameAt(5, 5), 6, 4, "room");
    EXPECT_EQ(joined(rowsOf(w)), joined(c.expected)) << c.label;
    EXPECT_DOUBLE_EQ(w.resolutionM(), 0.10) << c.label;
    EXPECT_EQ(w.name(), "room");
  }
}

// A convex room: a cell is free iff its closed square lies inside the closed room, i.e. all four corners do.
bool cornersInsideSquareRoom(const GridFrame& f, int col, int row, double sideCm) {
  for (const double dc : {-0.5, 0.5}) {
    for (const double dr : {-0.5, 0.5}) {
      const Vec2 p = f.toPlane(Vec2(col + dc, row + dr));
      const double eps = 1e-6;
      if (p.x() < -eps || p.y() < -eps || p.x() > sideCm + eps || p.y() > sideCm + eps) return false;
    }
  }
  return true;
}

TEST(TruthRaster, TurnedSquareRoomAgreesWithTheCornerTest) {
  struct Turn {
    double headingDeg, offsetCm;
  };
  const double side = 80.0;
  for (const Turn t : {Turn{10.0, 0.0}, Turn{10.0, 3.3}, Turn{-10.0, 0.0}, Turn{33.0, 1.7}, Turn{0.0, 0.0}}) {
    Scene scene;
    scene.addRing(box(0, 0, side, side));
    scene.finish();
    const Placement p = placeOnGrid(scene, Vec2(45 + t.offsetCm, 45 - t.offsetCm), t.headingDeg, 10.0);
    const World w = rasterizeScene(scene, p.frame, p.width, p.height, "turned");
    int free = 0;
    for (int r = 0; r < w.height(); ++r) {
      for (int c = 0; c < w.width(); ++c) {
        EXPECT_EQ(w.blocked(c, r), !cornersInsideSquareRoom(p.frame, c, r, side))
            << "heading " << t.headingDeg << " offset " << t.offsetCm << " cell " << c << "," << r;
        free += w.blocked(c, r) ? 0 : 1;
      }
    }
    // The free cells fit inside the room; a square grid holds fewer of them when turned.
    EXPECT_LE(free * 100.0, side * side) << t.headingDeg;
    EXPECT_GT(free, 0) << t.headingDeg;
    if (t.headingDeg == 0.0) {
      EXPECT_EQ(free, 64);
    } else {
      EXPECT_LT(free, 64) << t.headingDeg;
    }
  }
}

TEST(TruthRaster, OpenWallsAndDiscsDoNotChangeTheEvenOddRule) {
  Scene scene;
  scene.addRing(box(0, 0, 40, 40));
  scene.addRing(box(10, 10, 30, 30));  // a solid block inside the room (even-odd: solid again)
  scene.addWall(Edge{Vec2(2, 5), Vec2(38, 5)});
  scene.finish();
  const World w = rasterizeScene(scene, frameAt(5, 5), 4, 4, "block");
  EXPECT_EQ(joined(rowsOf(w)), joined({"####", ".##.", ".##.", "...."}));
}

}  // namespace
}  // namespace nxtmap::sim
