// SonarModel with `typical` against the published simulator: a copy of its ping (SimRobot::ping over the
// raster World, before the Scene) on a traced raster room gives the same readings from the same draws.
#include "host/sim/RayCast.hpp"
#include "host/sim/SonarModel.hpp"
#include "host/sim/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace nxtmap::sim {
namespace {

constexpr double kReach = 255.0;

bool todaysChance(double p, std::mt19937_64& rng) {
  if (p <= 0.0) return false;
  return std::uniform_real_distribution<double>(0.0, 1.0)(rng) < p;
}

int todaysPing(const World& world, double cellCm, const SonarNoise& n, double x, double y, double axis,
               bool othersFiring, std::mt19937_64& rng) {
  if (todaysChance(n.dropoutProb, rng)) return 255;
  if (othersFiring && todaysChance(n.crosstalkProb, rng)) return std::uniform_int_distribution<int>(3, 50)(rng);
  RayHit best;
  const int rays = n.coneHalfAngleDeg > 0.0 ? 9 : 1;
  for (int i = 0; i < rays; ++i) {
    const double offset = rays == 1 ? 0.0 : n.coneHalfAngleDeg * (2.0 * i / (rays - 1) - 1.0);
    const RayHit h = castRay(world, cellCm, x, y, axis + offset, kReach);
    if (offset != 0.0 && h.incidenceDeg > n.specularAngleDeg) continue;
    if (h.hit && (!best.hit || h.distanceCm < best.distanceCm)) best = h;
  }
  if (!best.hit) return 255;
  if (best.incidenceDeg > n.specularAngleDeg && todaysChance(n.specularMissProb, rng)) return 255;
  const double g = n.rangeSigmaCm > 0.0 ? std::normal_distribution<double>(0.0, n.rangeSigmaCm)(rng) : 0.0;
  const double reading = best.distanceCm + n.biasCm + g;
  return static_cast<int>(std::min<long>(std::lround(std::clamp(reading, 0.0, 255.0)), 255));
}

// Every face between a blocked cell (outside the map counts) and a free one, as a wall, in a ring around all.
Scene traced(const World& world, double cellCm) {
  Scene scene;
  scene.addRing(Ring{{Vec2(-1000, -1000), Vec2(1000, -1000), Vec2(1000, 1000), Vec2(-1000, 1000)}, Surface::Hard});
  for (int r = -1; r <= world.height(); ++r) {
    for (int c = -1; c <= world.width(); ++c) {
      if (!world.blocked(c, r)) continue;
      const double x0 = c * cellCm, y0 = r * cellCm, x1 = x0 + cellCm, y1 = y0 + cellCm;
      if (world.inside(c + 1, r) && !world.blocked(c + 1, r)) scene.addWall(Edge{Vec2(x1, y0), Vec2(x1, y1)});
      if (world.inside(c - 1, r) && !world.blocked(c - 1, r)) scene.addWall(Edge{Vec2(x0, y0), Vec2(x0, y1)});
      if (world.inside(c, r + 1) && !world.blocked(c, r + 1)) scene.addWall(Edge{Vec2(x0, y1), Vec2(x1, y1)});
      if (world.inside(c, r - 1) && !world.blocked(c, r - 1)) scene.addWall(Edge{Vec2(x0, y0), Vec2(x1, y0)});
    }
  }
  scene.finish();
  return scene;
}

TEST(SonarModel, TypicalDrawsAndReadsExactlyAsThePublishedSimulator) {
  const World world = World::fromRows({
      "......................",
      "..##..........#.......",
      "..##..........#...##..",
      "..............#...##..",
      "......####............",
      "......####.......#....",
      "..#..............#....",
      "..#......##......#....",
      "..........#...........",
      "......................",
  });
  const double cellCm = 10.0;
  const Scene scene = traced(world, cellCm);
  const SonarNoise typical = sonarPreset("typical");
  int echoes = 0, specials = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    SonarModel model(typical, kReach, seed);
    std::mt19937_64 ours(seed), theirs(seed), poses(seed + 1000);
    for (int k = 0; k < 400; ++k) {
      int c = 0, r = 0;
      do {
        c = std::uniform_int_distribution<int>(0, world.width() - 1)(poses);
        r = std::uniform_int_distribution<int>(0, world.height() - 1)(poses);
      } while (world.blocked(c, r));
      const double x = (c + std::uniform_real_distribution<double>(0.05, 0.95)(poses)) * cellCm;
      const double y = (r + std::uniform_real_distribution<double>(0.05, 0.95)(poses)) * cellCm;
      const int sensor = std::uniform_int_distribution<int>(0, 3)(poses);
      const bool square = std::uniform_int_distribution<int>(0, 1)(poses) == 1;
      const double heading = square ? 90.0 * std::uniform_int_distribution<int>(0, 3)(poses)
                                    : std::uniform_real_distribution<double>(0.0, 360.0)(poses);
      const bool others = std::uniform_int_distribution<int>(0, 3)(poses) == 0;
      const double axis = heading + 90.0 * sensor;
      const int want = todaysPing(world, cellCm, typical, x, y, axis, others, theirs);
      const int got = model.ping(scene, Vec2(x, y), axis, sensor, 10.0 * k, others, ours);
      ASSERT_EQ(got, want) << "seed " << seed << " ping " << k << " at " << x << "," << y << " axis " << axis;
      if (got != 255) ++echoes;
      if (got == 255 || got <= 2) ++specials;
    }
    EXPECT_EQ(ours(), theirs()) << "seed " << seed;  // the generators stayed in step
  }
  EXPECT_GT(echoes, 4000);  // the comparison is mostly of echoes, not of shared 255s
  EXPECT_GT(specials, 0);
}

}  // namespace
}  // namespace nxtmap::sim
