// Scene against tables: casts in a room and at its elements, solid points by the even-odd rule, edges and
// bounds, a hall 300 m across, and bodies touching.
#include "host/sim/Scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/sim/SceneShapes.hpp"

namespace nxtmap::sim {
namespace {

using test::box;
using test::kPi;
using test::square;

// A 400 x 300 cm room.
Scene room() {
  Scene s;
  s.addRing(box(0, 0, 400, 300));
  s.finish();
  return s;
}

struct CastCase {
  const char* label;
  Vec2 origin;
  double deg, maxCm;
  bool hit;
  double distanceCm, incidenceDeg;
};

TEST(SceneCast, RoomTable) {
  const double r2 = std::sqrt(2.0);
  const std::vector<CastCase> cases = {
      {"north", {100, 100}, 0, 500, true, 100, 0},
      {"east", {100, 100}, 90, 500, true, 300, 0},
      {"south", {100, 100}, 180, 500, true, 200, 0},
      {"west", {100, 100}, 270, 500, true, 100, 0},
      {"north-east to the top wall", {100, 100}, 45, 500, true, 100 * r2, 45},
      {"west-north-west to the left wall", {100, 100}, 300, 500, true, 100 / std::cos(kPi / 6), 30},
      {"just short of the wall", {100, 100}, 0, 99.9, false, 0, 0},
      {"exactly the range", {100, 100}, 0, 100, true, 100, 0},
      {"a negative compass direction", {100, 100}, -90, 500, true, 100, 0},
      {"beyond a full turn", {100, 100}, 450, 500, true, 300, 0},
      {"from outside the room", {500, 100}, 270, 500, true, 0, 0},
      {"from on the wall", {0, 100}, 90, 500, true, 0, 0},
      {"from a corner", {400, 300}, 315, 500, true, 0, 0},
  };
  const Scene s = room();
  for (const CastCase& c : cases) {
    const SceneHit h = s.cast(c.origin, c.deg, c.maxCm);
    EXPECT_EQ(h.hit, c.hit) << c.label;
    if (!h.hit) continue;
    EXPECT_NEAR(h.distanceCm, c.distanceCm, 1e-9) << c.label;
    EXPECT_NEAR(h.incidenceDeg, c.incidenceDeg, 1e-9) << c.label;
  }
}

TEST(SceneCast, ElementsAnswerWithTheirSurfaceAndANormalTowardsTheOrigin) {
  Scene s;
  s.addRing(box(0, 0, 400, 300, Surface::Soft));
  s.addWall(Edge{Vec2(200, 50), Vec2(200, 250), Surface::Thin});
  s.addDisc(Disc{Vec2(300, 150), 10, Surface::Hard});
  s.finish();
  struct Case {
    Vec2 origin;
    double deg, distanceCm, incidenceDeg;
    Surface surface;
    Vec2 normal;
  };
  const double off = 10 - std::sqrt(100.0 - 25.0);  // the disc's near side 5 cm off its centre line
  const std::vector<Case> cases = {
      {{100, 100}, 90, 100, 0, Surface::Thin, {-1, 0}},                          // wall from the left
      {{250, 100}, 270, 50, 0, Surface::Thin, {1, 0}},                           // wall from the right
      {{250, 150}, 90, 40, 0, Surface::Hard, {-1, 0}},                           // disc square on
      {{250, 155}, 90, 40 + off, 30, Surface::Hard, {-std::cos(kPi / 6), 0.5}},  // disc off centre
      {{200, 280}, 0, 30, 90, Surface::Thin, {1, 0}},                            // along the wall: its end
      {{100, 100}, 0, 100, 0, Surface::Soft, {0, 1}},                            // the room
  };
  for (const Case& c : cases) {
    const SceneHit h = s.cast(c.origin, c.deg, 1000);
    ASSERT_TRUE(h.hit) << c.deg;
    EXPECT_NEAR(h.distanceCm, c.distanceCm, 1e-9) << c.origin.transpose() << " " << c.deg;
    EXPECT_NEAR(h.incidenceDeg, c.incidenceDeg, 1e-7) << c.origin.transpose() << " " << c.deg;
    EXPECT_EQ(h.surface, c.surface) << c.origin.transpose() << " " << c.deg;
    if (c.incidenceDeg < 90) {
      EXPECT_NEAR((h.normal - c.normal).norm(), 0.0, 1e-9) << c.origin.transpose();
    }
  }
}

TEST(SceneSolid, EvenOddOverRingsDiscsAndWalls) {
  Scene s;
  s.addRing(box(0, 0, 400, 300));    // the room: free inside
  s.addRing(box(50, 50, 150, 150));  // a sofa: solid again
  s.addRing(box(90, 90, 110, 110));  // a hole through the sofa: free
  s.addWall(Edge{Vec2(200, 50), Vec2(300, 250)});
  s.addDisc(Disc{Vec2(350, 50), 5});
  s.finish();
  struct Case {
    Vec2 p;
    bool solid;
  };
  const std::vector<Case> cases = {
      {{20, 20}, false},  {{-1, 20}, true},   {{500, 500}, true}, {{0, 20}, true},
      {{400, 300}, true}, {{60, 60}, true},   {{50, 100}, true},  {{100, 100}, false},
      {{95, 105}, false}, {{110, 100}, true}, {{250, 150}, true}, {{250, 151}, false},
      {{350, 50}, true},  {{354, 53}, true},  {{354, 54}, false}, {{399.999, 299.999}, false},
  };
  for (const Case& c : cases) EXPECT_EQ(s.solidAt(c.p), c.solid) << c.p.transpose();
  EXPECT_TRUE(s.cast(Vec2(100, 100), 0, 100).hit);  // the hole's side at 10 cm
  EXPECT_NEAR(s.cast(Vec2(100, 100), 0, 100).distanceCm, 10, 1e-12);
  EXPECT_NEAR(s.cast(Vec2(100, 160), 0, 500).distanceCm, 10, 1e-12);  // the sofa from outside
}

TEST(SceneSolid, AnEmptySceneIsSolidEverywhere) {
  Scene s;
  s.finish();
  EXPECT_TRUE(s.solidAt(Vec2(0, 0)));
  EXPECT_TRUE(s.solidAt(Vec2(-50, 1e4)));
  const SceneHit h = s.cast(Vec2(3, 4), 10, 255);
  EXPECT_TRUE(h.hit);
  EXPECT_EQ(h.distanceCm, 0.0);
  EXPECT_TRUE(s.edges().empty());
}

TEST(SceneEdges, RingSidesThenWallsAndTheBoundsAroundAll) {
  Scene s;
  s.addWall(Edge{Vec2(-20, 5), Vec2(10, 5)});
  s.addRing(Ring{{Vec2(0, 0), Vec2(100, 0), Vec2(50, 80)}, Surface::Hard});
  s.addDisc(Disc{Vec2(90, 90), 20});
  s.finish();
  ASSERT_EQ(s.edges().size(), 4u);
  EXPECT_EQ(s.edges()[2].a, Vec2(50, 80));
  EXPECT_EQ(s.edges()[2].b, Vec2(0, 0));
  EXPECT_EQ(s.edges()[3].a, Vec2(-20, 5));
  const SceneBounds b = s.bounds();
  EXPECT_EQ(b.minX, -20);
  EXPECT_EQ(b.minY, 0);
  EXPECT_EQ(b.maxX, 110);
  EXPECT_EQ(b.maxY, 110);
}

TEST(SceneCast, AHallThreeHundredMetresAcrossStaysExact) {
  Scene s;
  s.addRing(box(0, 0, 30000, 20000));
  s.addDisc(Disc{Vec2(29000, 10000), 50});
  s.finish();
  EXPECT_NEAR(s.cast(Vec2(100, 10000), 90, 1e6).distanceCm, 29000 - 50 - 100, 1e-6);
  EXPECT_NEAR(s.cast(Vec2(100, 100), 135, 1e6).distanceCm, 19900 * std::sqrt(2.0), 1e-6);
  EXPECT_FALSE(s.cast(Vec2(100, 100), 135, 255).hit);
  EXPECT_FALSE(s.solidAt(Vec2(15000, 10000)));
  EXPECT_TRUE(s.solidAt(Vec2(29000, 10040)));
}

TEST(SceneTouches, Table) {
  Scene s;
  s.addRing(box(0, 0, 400, 300));
  s.addRing(box(300, 200, 310, 210));  // a pillar
  s.addRing(box(20, 200, 120, 290));   // a sofa
  s.addWall(Edge{Vec2(200, 50), Vec2(200, 150)});
  s.addDisc(Disc{Vec2(100, 100), 3});
  s.finish();
  struct Case {
    const char* label;
    std::vector<Vec2> body;
    bool touches;
  };
  const std::vector<Case> cases = {
      {"free space", square({300, 80}, 8, 0.3), false},
      {"across the room's side", square({5, 80}, 8, 0), true},
      {"a side lying on the room's side", square({8, 80}, 8, 0), true},
      {"a corner a hair from the wall", square({191.999, 100}, 8, 0), false},
      {"a corner on the wall", square({192, 100}, 8, 0), true},
      {"across the wall's end", square({200, 45}, 8, 0.5), true},
      {"around a leg", square({100, 100}, 8, 0.2), true},
      {"beside a leg", square({100, 112}, 8, 0), false},
      {"around the pillar", square({305, 205}, 8, 0.1), true},
      {"inside the sofa", square({70, 245}, 8, 0.4), true},
      {"outside the room", square({600, 80}, 8, 0), true},
      {"one free point", {Vec2(300, 80)}, false},
      {"one point in the sofa", {Vec2(70, 245)}, true},
      {"a segment across the wall", {Vec2(190, 100), Vec2(210, 100)}, true},
      {"a free segment", {Vec2(190, 100), Vec2(150, 100)}, false},
  };
  for (const Case& c : cases) EXPECT_EQ(s.touches(c.body), c.touches) << c.label;
}

}  // namespace
}  // namespace nxtmap::sim
