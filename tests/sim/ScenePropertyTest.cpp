// Scene against brute force over every element of a furnished hall: cast, solidAt and touches.
#include "host/sim/Scene.hpp"

#include "host/sim/RayCast.hpp"
#include "host/sim/SceneGeometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "tests/sim/SceneShapes.hpp"

namespace nxtmap::sim {
namespace {

using test::box;
using test::kPi;
using test::square;

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
