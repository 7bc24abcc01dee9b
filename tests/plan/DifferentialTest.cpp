// Differential test: astar, jps, jps+ and plain Dijkstra agree on random grids (found or not, and the length);
// every path is legal and as long as reported; the published search finds a path exactly when one exists.
#include <gtest/gtest.h>

#include <random>

#include "host/plan/Planner.hpp"

namespace nxtmap::plan {
namespace {

mapio::OccupancyMap randomMap(std::mt19937& rng, int w, int h, double blocked, double unknown) {
  mapio::OccupancyMap m(w, h, mapio::Occupancy::Free);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const double x = u(rng);
      if (x < blocked) {
        m.set(c, r, mapio::Occupancy::Occupied);
      } else if (x < blocked + unknown) {
        m.set(c, r, mapio::Occupancy::Unknown);
      }
    }
  }
  return m;
}

MapCell randomFreeCell(std::mt19937& rng, const Traversability& grid) {
  std::uniform_int_distribution<int> col(0, grid.width() - 1), row(0, grid.height() - 1);
  for (int tries = 0; tries < 1000; ++tries) {
    const MapCell c{col(rng), row(rng)};
    if (grid.passable(c)) return c;
  }
  return MapCell{-1, -1};
}

TEST(Differential, AStarJpsDijkstraAndSeedOnRandomGrids) {
  std::mt19937 rng(20261122);
  auto astar = makePlanner(Algorithm::AStar);
  auto jps = makePlanner(Algorithm::Jps);
  auto jpsPlus = makePlanner(Algorithm::JpsPlus);
  auto dijkstra = makePlanner(Algorithm::Dijkstra);
  auto seed = makePlanner(Algorithm::Seed);
  const double densities[] = {0.0, 0.1, 0.2, 0.3, 0.4};
  int found = 0, notFound = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::uniform_int_distribution<int> side(1, 40);
    const int w = side(rng), h = side(rng);
    const mapio::OccupancyMap map = randomMap(rng, w, h, densities[trial % 5], trial % 3 == 0 ? 0.05 : 0.0);
    PlanOptions options;
    options.unknownTraversable = trial % 7 == 0;
    options.clearanceCells = trial % 11 == 0 ? 1 : 0;
    const Traversability grid(map, options.unknownTraversable, options.clearanceCells);
    for (int q = 0; q < 5; ++q) {
      const MapCell from = randomFreeCell(rng, grid);
      const MapCell to = randomFreeCell(rng, grid);
      if (from.col < 0 || to.col < 0) continue;
      const PlanResult ref = dijkstra->plan(grid, from, to, options);
      const std::string where = "trial " + std::to_string(trial) + " " + std::to_string(w) + "x" + std::to_string(h) +
                                " from " + std::to_string(from.col) + "," + std::to_string(from.row) + " to " +
                                std::to_string(to.col) + "," + std::to_string(to.row);
      ASSERT_TRUE(ref.status == PlanStatus::Found || ref.status == PlanStatus::NoPath) << where;
      ref.found() ? ++found : ++notFound;
      for (Planner* p : {astar.get(), jps.get(), jpsPlus.get(), seed.get()}) {
        const PlanResult r = p->plan(grid, from, to, options);
        const std::string who = where + " " + algorithmName(p->algorithm());
        ASSERT_EQ(r.status, ref.status) << who;
        if (!r.found()) continue;
        double walked = 0;
        ASSERT_TRUE(grid.validPath(r.path, walked)) << who;
        EXPECT_EQ(r.path.front(), from) << who;
        EXPECT_EQ(r.path.back(), to) << who;
        EXPECT_NEAR(walked, r.length, 1e-9) << who;
        if (p == seed.get()) {
          EXPECT_GE(r.length, ref.length - 1e-9) << who;
        } else {
          EXPECT_NEAR(r.length, ref.length, 1e-9) << who;
        }
      }
    }
  }
  // The sample really covers both outcomes.
  EXPECT_GT(found, 500);
  EXPECT_GT(notFound, 50);
}

// Grids wider and taller than 64 cells, so that jps's bit scans cross word boundaries in rows and columns;
// the diagonal walks with intermediate pruning meet many obstacles.
TEST(Differential, JpsMatchesAStarOnGridsSpanningSeveralWords) {
  std::mt19937 rng(512);
  auto astar = makePlanner(Algorithm::AStar);
  auto jps = makePlanner(Algorithm::Jps);
  auto jpsPlus = makePlanner(Algorithm::JpsPlus);
  const double densities[] = {0.05, 0.1, 0.2, 0.3};
  int found = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::uniform_int_distribution<int> side(60, 200);
    const int w = side(rng), h = side(rng);
    const mapio::OccupancyMap map = randomMap(rng, w, h, densities[trial % 4], trial % 3 == 0 ? 0.03 : 0.0);
    PlanOptions options;
    options.unknownTraversable = trial % 5 == 0;
    options.clearanceCells = trial % 6 == 1 ? 1 : 0;
    const Traversability grid(map, options.unknownTraversable, options.clearanceCells);
    for (int q = 0; q < 15; ++q) {
      const MapCell from = randomFreeCell(rng, grid), to = randomFreeCell(rng, grid);
      if (from.col < 0 || to.col < 0) continue;
      const PlanResult ref = astar->plan(grid, from, to, options);
      const std::string where = "trial " + std::to_string(trial) + " " + std::to_string(w) + "x" + std::to_string(h) +
                                " from " + std::to_string(from.col) + "," + std::to_string(from.row) + " to " +
                                std::to_string(to.col) + "," + std::to_string(to.row);
      if (ref.found()) ++found;
      for (Planner* p : {jps.get(), jpsPlus.get()}) {
        const PlanResult r = p->plan(grid, from, to, options);
        const std::string who = where + " " + algorithmName(p->algorithm());
        ASSERT_EQ(r.status, ref.status) << who;
        if (!r.found()) continue;
        double walked = 0;
        ASSERT_TRUE(grid.validPath(r.path, walked)) << who;
        EXPECT_EQ(r.path.front(), from) << who;
        EXPECT_EQ(r.path.back(), to) << who;
        EXPECT_NEAR(walked, r.length, 1e-9) << who;
        EXPECT_NEAR(r.length, ref.length, 1e-9) << who;
      }
    }
  }
  EXPECT_GT(found, 100);
}

TEST(Differential, JpsExpandsFewerNodesThanAStarOnOpenGrids) {
  std::mt19937 rng(7);
  const mapio::OccupancyMap map = randomMap(rng, 200, 200, 0.05, 0.0);
  const Traversability grid(map);
  auto astar = makePlanner(Algorithm::AStar);
  auto jps = makePlanner(Algorithm::Jps);
  uint64_t a = 0, j = 0;
  for (int q = 0; q < 20; ++q) {
    const MapCell from = randomFreeCell(rng, grid), to = randomFreeCell(rng, grid);
    const PlanResult ra = astar->plan(grid, from, to), rj = jps->plan(grid, from, to);
    ASSERT_EQ(ra.status, rj.status);
    if (ra.found()) {
      EXPECT_NEAR(ra.length, rj.length, 1e-9);
    }
    a += ra.nodesExpanded;
    j += rj.nodesExpanded;
  }
  EXPECT_LT(j * 2, a);
}

}  // namespace
}  // namespace nxtmap::plan
