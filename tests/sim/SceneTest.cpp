#include "host/sim/Scene.hpp"

#include "host/sim/RayCast.hpp"
#include "host/sim/SceneGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace nxtmap::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

Ring box(double x0, double y0, double x1, double y1, Surface surface = Surface::Hard) {
  return Ring{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, surface};
}

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

// A furnished hall: turned boxes (rings), a slanted wall, legs. Brute force over every element is the
// reference for cast, solidAt and touches.
struct Furnished {
  Scene scene;
  std::vector<Edge> ringSides, walls;
  std::vector<Disc> discs;
};

Furnished furnished(unsigned seed) {
  Furnished f;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Ring> rings = {box(0, 0, 1500, 900)};
  for (int i = 0; i < 25; ++i) {
    const Vec2 c(100 + 1300 * u(rng), 100 + 700 * u(rng));
    const double a = 2 * kPi * u(rng), w = 10 + 60 * u(rng), h = 10 + 60 * u(rng);
    const Vec2 ax(std::cos(a), std::sin(a)), ay(-std::sin(a), std::cos(a));
    rings.push_back(Ring{{c - w * ax - h * ay, c + w * ax - h * ay, c + w * ax + h * ay, c - w * ax + h * ay},
                         i % 2 ? Surface::Soft : Surface::Hard});
  }
  for (int i = 0; i < 10; ++i) {
    const Vec2 a(50 + 1400 * u(rng), 50 + 800 * u(rng));
    f.walls.push_back(Edge{a, a + Vec2(300 * u(rng) - 150, 300 * u(rng) - 150), Surface::Soft});
  }
  for (int i = 0; i < 20; ++i) f.discs.push_back(Disc{Vec2(50 + 1400 * u(rng), 50 + 800 * u(rng)), 1 + 4 * u(rng)});
  for (const Ring& r : rings) {
    for (size_t i = 0; i < r.points.size(); ++i) {
      f.ringSides.push_back(Edge{r.points[i], r.points[(i + 1) % r.points.size()], r.surface});
    }
    f.scene.addRing(r);
  }
  for (const Edge& w : f.walls) f.scene.addWall(w);
  for (const Disc& d : f.discs) f.scene.addDisc(d);
  f.scene.finish();
  return f;
}

double nearestElementCm(const Furnished& f, const Vec2& p) {
  double near = std::numeric_limits<double>::infinity();
  for (const auto* list : {&f.ringSides, &f.walls}) {
    for (const Edge& e : *list) near = std::min(near, geometry::pointSegmentDistance(p, e.a, e.b));
  }
  for (const Disc& d : f.discs) near = std::min(near, std::fabs((p - d.centre).norm() - d.radiusCm));
  return near;
}

bool bruteSolid(const Furnished& f, const Vec2& p) {
  bool inside = false;
  for (const Edge& e : f.ringSides) {
    if ((e.a.y() > p.y()) != (e.b.y() > p.y()) &&
        p.x() < e.a.x() + (p.y() - e.a.y()) * (e.b.x() - e.a.x()) / (e.b.y() - e.a.y())) {
      inside = !inside;
    }
  }
  for (const Disc& d : f.discs) inside = inside && (p - d.centre).norm() > d.radiusCm;
  return !inside;
}

TEST(SceneProperty, CastAndSolidAtAgreeWithBruteForce) {
  for (unsigned seed = 1; seed <= 2; ++seed) {
    const Furnished f = furnished(seed);
    std::mt19937 rng(seed * 77);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int casts = 0;
    for (int i = 0; i < 1500; ++i) {
      const Vec2 p(-20 + 1540 * u(rng), -20 + 940 * u(rng));
      if (nearestElementCm(f, p) < 1e-6) continue;
      const bool solid = bruteSolid(f, p);
      ASSERT_EQ(f.scene.solidAt(p), solid) << "seed " << seed << " at " << p.transpose();
      if (solid) continue;
      const double deg = i % 7 == 0 ? 90.0 * (i % 4) : 360 * u(rng);
      const double maxCm = i % 3 == 0 ? 255.0 : 2000.0;
      double dx = 0, dy = 0;
      directionVector(deg, dx, dy);
      const Vec2 d(dx, dy);
      double best = std::numeric_limits<double>::infinity();
      for (const auto* list : {&f.ringSides, &f.walls}) {
        for (const Edge& e : *list) best = std::min(best, geometry::raySegment(p, d, e.a, e.b));
      }
      for (const Disc& disc : f.discs) best = std::min(best, geometry::rayDisc(p, d, disc.centre, disc.radiusCm));
      const SceneHit h = f.scene.cast(p, deg, maxCm);
      ASSERT_EQ(h.hit, best <= maxCm) << "seed " << seed << " " << p.transpose() << " deg " << deg;
      if (h.hit) {
        ASSERT_NEAR(h.distanceCm, best, 1e-9) << "seed " << seed << " " << p.transpose() << " deg " << deg;
        EXPECT_LE(h.normal.dot(d), 1e-12);
        EXPECT_GE(h.incidenceDeg, 0.0);
        EXPECT_LE(h.incidenceDeg, 90.0);
      }
      ++casts;
    }
    EXPECT_GT(casts, 500) << seed;
  }
}

// The body: a square of side 2h centred at c, turned by a radians.
std::vector<Vec2> square(const Vec2& c, double h, double a) {
  const Vec2 ax(std::cos(a), std::sin(a)), ay(-std::sin(a), std::cos(a));
  return {c - h * ax - h * ay, c + h * ax - h * ay, c + h * ax + h * ay, c - h * ax + h * ay};
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

TEST(SceneProperty, TouchesAgreesWithBruteForce) {
  const Furnished f = furnished(9);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int touching = 0, clear = 0;
  for (int i = 0; i < 800; ++i) {
    const double half = 4 + 10 * u(rng);
    const std::vector<Vec2> body = square(Vec2(1500 * u(rng), 900 * u(rng)), half, 2 * kPi * u(rng));
    Vec2 centroid(0, 0);
    for (const Vec2& p : body) centroid += p / 4.0;
    bool expect = bruteSolid(f, centroid);
    for (const auto* list : {&f.ringSides, &f.walls}) {
      for (const Edge& e : *list) {
        if (geometry::pointSegmentDistance(centroid, e.a, e.b) > 1.5 * half) continue;  // too far to touch
        expect = expect || geometry::insideConvex(body, e.a);
        for (size_t k = 0; k < 4; ++k) expect = expect || geometry::segmentsTouch(e.a, e.b, body[k], body[(k + 1) % 4]);
      }
    }
    for (const Disc& d : f.discs) {
      expect = expect || geometry::insideConvex(body, d.centre);
      for (size_t k = 0; k < 4; ++k) {
        expect = expect || geometry::pointSegmentDistance(d.centre, body[k], body[(k + 1) % 4]) <= d.radiusCm;
      }
    }
    ASSERT_EQ(f.scene.touches(body), expect) << "body at " << centroid.transpose();
    (expect ? touching : clear)++;
  }
  EXPECT_GT(touching, 100);
  EXPECT_GT(clear, 100);
}

}  // namespace
}  // namespace nxtmap::sim
