#include "host/sim/SceneFromRaster.hpp"

#include "host/sim/RayCast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace nxtmap::sim {
namespace {

const std::string kWorlds = std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/";
const char* const kPublished[] = {"occupancy-089", "occupancy-095", "occupancy-101", "occupancy-107", "occupancy-113",
                                  "occupancy-120", "occupancy-127", "occupancy-132", "occupancy-139"};

World published(const std::string& name) {
  WorldLoad l = World::loadMovingAi(kWorlds + name + ".map");
  EXPECT_TRUE(l.world) << l.error;
  return *l.world;
}

// Hand-made rooms: corners where blocked cells meet only diagonally, islands, a room with no border
// (the map's edge is the wall), a single free cell, a map with nothing free.
struct Room {
  const char* label;
  std::vector<std::string> rows;
  double resolutionM;
};
const std::vector<Room> kRooms = {
    {"no border", {"....", "....", "...."}, 0.10},
    {"one free cell", {"###", "#.#", "###"}, 0.20},
    {"diagonal corners", {"#.#.", ".#.#", "#.#.", "...."}, 0.10},
    {"island and a notch", {"########", "#......#", "#.##...#", "#.##.#.#", "#....#..", "########"}, 0.05},
    {"all blocked", {"###", "###"}, 0.10},
    {"stairs", {"#.....", "##....", ".##...", "..##..", "...##.", "....##"}, 0.13},
};

// Thousands of rays from random points strictly inside free cells, a fifth of them along the four axes,
// and random points anywhere for solidAt: the traced scene answers as the raster does.
void expectSameAsRaster(const World& w, unsigned seed, int rays) {
  const Scene scene = traceRaster(w);
  const double cell = w.resolutionM() * 100.0;
  std::vector<std::pair<int, int>> freeCells;
  for (int r = 0; r < w.height(); ++r) {
    for (int c = 0; c < w.width(); ++c) {
      if (!w.blocked(c, r)) freeCells.emplace_back(c, r);
    }
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto inside = [&]() { return 1e-6 + (1.0 - 2e-6) * u(rng); };  // off the cell lines
  for (int i = 0; i < rays && !freeCells.empty(); ++i) {
    const auto [c, r] = freeCells[rng() % freeCells.size()];
    const double x = (c + inside()) * cell, y = (r + inside()) * cell;
    const double deg = i % 5 == 0 ? 90.0 * (i / 5 % 4) : 360.0 * u(rng);
    const double maxCm = i % 2 ? 255.0 : 1e5;
    const RayHit want = castRay(w, cell, x, y, deg, maxCm);
    const SceneHit got = scene.cast(Vec2(x, y), deg, maxCm);
    ASSERT_EQ(got.hit, want.hit) << w.name() << " from " << x << ", " << y << " deg " << deg;
    ASSERT_NEAR(got.distanceCm, want.distanceCm, 1e-9) << w.name() << " from " << x << ", " << y << " deg " << deg;
    ASSERT_NEAR(got.incidenceDeg, want.incidenceDeg, 1e-9) << w.name() << " from " << x << ", " << y << " deg " << deg;
  }
  for (int i = 0; i < rays; ++i) {
    const double gx = -2.0 + (w.width() + 4) * u(rng), gy = -2.0 + (w.height() + 4) * u(rng);
    if (std::fabs(gx - std::round(gx)) < 1e-6 || std::fabs(gy - std::round(gy)) < 1e-6) continue;
    const bool want = w.blocked(static_cast<int>(std::floor(gx)), static_cast<int>(std::floor(gy)));
    ASSERT_EQ(scene.solidAt(Vec2(gx * cell, gy * cell)), want) << w.name() << " at cell " << gx << ", " << gy;
  }
}

TEST(SceneFromRaster, PublishedWorldsCastAsTheRasterDoes) {
  unsigned seed = 1;
  for (const char* name : kPublished) expectSameAsRaster(published(name), seed++, 4000);
}

TEST(SceneFromRaster, HandMadeRoomsCastAsTheRasterDoes) {
  unsigned seed = 100;
  for (const Room& room : kRooms) {
    SCOPED_TRACE(room.label);
    expectSameAsRaster(World::fromRows(room.rows, room.resolutionM), seed++, 3000);
  }
}

// The rings' shape: axis-parallel sides on the cell lines, no two consecutive sides in one line, free cells
// on the left of every side (as seen in the plane, y down) and blocked ones on the right, and together the
// sides cover exactly the blocked/free faces of the raster.
TEST(SceneFromRaster, RingsFollowTheFacesWithFreeCellsOnTheLeft) {
  std::vector<World> worlds;
  for (const char* name : kPublished) worlds.push_back(published(name));
  for (const Room& room : kRooms) worlds.push_back(World::fromRows(room.rows, room.resolutionM));
  for (const World& w : worlds) {
    const double cell = w.resolutionM() * 100.0;
    const Scene scene = traceRaster(w);
    long faces = 0;
    for (int r = -1; r <= w.height(); ++r) {
      for (int c = -1; c <= w.width(); ++c) {
        faces += (w.blocked(c, r) != w.blocked(c + 1, r)) + (w.blocked(c, r) != w.blocked(c, r + 1));
      }
    }
    double sideCells = 0.0;
    for (const Ring& ring : scene.rings()) {
      const size_t n = ring.points.size();
      ASSERT_GE(n, 4u) << w.name();
      EXPECT_EQ(ring.surface, Surface::Hard);
      for (size_t i = 0; i < n; ++i) {
        const Vec2 a = ring.points[i], b = ring.points[(i + 1) % n], next = ring.points[(i + 2) % n];
        const Vec2 along = b - a;
        ASSERT_TRUE((along.x() == 0) != (along.y() == 0)) << w.name() << " side " << a.transpose();
        EXPECT_NE(along.normalized().dot((next - b).normalized()), 1.0) << w.name() << " at " << b.transpose();
        sideCells += along.norm() / cell;
        const Vec2 mid = (a + b) / 2.0, left = Vec2(along.y(), -along.x()).normalized() * (cell / 4);
        const Vec2 freeSide = (mid + left) / cell, blockedSide = (mid - left) / cell;
        EXPECT_FALSE(w.blocked(static_cast<int>(std::floor(freeSide.x())), static_cast<int>(std::floor(freeSide.y()))))
            << w.name() << " side " << a.transpose() << " -> " << b.transpose();
        EXPECT_TRUE(
            w.blocked(static_cast<int>(std::floor(blockedSide.x())), static_cast<int>(std::floor(blockedSide.y()))))
            << w.name() << " side " << a.transpose() << " -> " << b.transpose();
      }
    }
    EXPECT_NEAR(sideCells, static_cast<double>(faces), 1e-6) << w.name();
  }
}

TEST(SceneFromRaster, RingCountsOfSimpleRooms) {
  struct Case {
    std::vector<std::string> rows;
    size_t rings, sides;
  };
  const std::vector<Case> cases = {
      {{"...", "..."}, 1, 4},                             // the map's border
      {{"###", "#.#", "###"}, 1, 4},                      // one cell
      {{".....", ".#...", "....."}, 2, 8},                // the border and an island
      {{"......", ".##...", ".#....", "......"}, 2, 10},  // an L-shaped island
      {{"##", "##"}, 0, 0},                               // nothing free
  };
  for (const Case& c : cases) {
    const Scene s = traceRaster(World::fromRows(c.rows));
    EXPECT_EQ(s.rings().size(), c.rings) << c.rows[0];
    EXPECT_EQ(s.edges().size(), c.sides) << c.rows[0];
  }
}

}  // namespace
}  // namespace nxtmap::sim
