// The published search: its child order, depth limit with tolerance, iterative deepening, node counts,
// and completeness on the Appendix A rooms.
#include <gtest/gtest.h>

#include "host/mapio/MapFiles.hpp"
#include "host/plan/DijkstraPlanner.hpp"
#include "host/plan/SeedSearch.hpp"
#include "tests/plan/PlanTestSupport.hpp"

namespace nxtmap::plan {
namespace {

using test::mapFromRows;

TEST(SeedSearch, ChildOrderIsThePublishedGroupOneOrderRotatedTowardsTheGoal) {
  // Goal up and right (thesis Group 1, y up; rows grow down here): (u+1,v+1), (u,v+1), (u+1,v), (u-1,v+1),
  // (u+1,v-1), then (u-1,v), (u,v-1), (u-1,v-1).
  int order[8];
  seedChildOrder(5, -3, order);
  const int expected[8][2] = {{1, -1}, {0, -1}, {1, 0}, {-1, -1}, {1, 1}, {-1, 0}, {0, 1}, {-1, 1}};
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(kSeedDirs[order[k]][0], expected[k][0]) << k;
    EXPECT_EQ(kSeedDirs[order[k]][1], expected[k][1]) << k;
  }
  // Goal straight left: W first, then SW?/NW by the same rotation (+45 counter-clockwise with y up = SW).
  seedChildOrder(-4, 0, order);
  EXPECT_EQ(kSeedDirs[order[0]][0], -1);
  EXPECT_EQ(kSeedDirs[order[0]][1], 0);
  EXPECT_EQ(kSeedDirs[order[7]][0], 1);  // straight away last
  EXPECT_EQ(kSeedDirs[order[7]][1], 0);
  // The five goal-facing moves never increase the straight-line distance by more than a side step.
  for (int dc = -3; dc <= 3; ++dc) {
    for (int dr = -3; dr <= 3; ++dr) {
      if (dc == 0 && dr == 0) continue;
      seedChildOrder(dc, dr, order);
      for (int k = 5; k < 8; ++k) {
        const int dot = kSeedDirs[order[k]][0] * dc + kSeedDirs[order[k]][1] * dr;
        EXPECT_LT(dot, 0 + (dc != 0 && dr != 0 ? 1 : 0)) << dc << "," << dr << " k " << k;
      }
    }
  }
}

TEST(SeedSearch, OpenCorridorIsFoundInOnePassVisitingOnlyThePath) {
  const mapio::OccupancyMap map = mapFromRows({"..........", "..........", ".........."});
  SeedSearch s;
  const PlanResult r = s.plan(map, {0, 1}, {9, 1});
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.path.size(), 10u);
  EXPECT_EQ(r.nodesExpanded, 10u);  // straight towards the goal: every node visited is on the path
  EXPECT_EQ(s.lastIterations(), 1);
  EXPECT_NEAR(r.length, 9.0, 1e-12);
}

TEST(SeedSearch, DepthLimitGrowsByTheConstantWhenTheDetourIsLong) {
  // A wall across the straight way: the straight-moves limit (8) is too short, the limit grows by c.
  const mapio::OccupancyMap map = mapFromRows({
      "..........",
      "..........",
      ".#######..",
      ".......#..",
      "..........",
  });
  for (int c : {1, 4, 8}) {
    SeedSearch s;
    PlanOptions o;
    o.seedDepthStep = c;
    const PlanResult r = s.plan(map, {3, 3}, {3, 0}, o);
    ASSERT_TRUE(r.found()) << c;
    EXPECT_GT(s.lastIterations(), 1) << c;
    double walked = 0;
    EXPECT_TRUE(Traversability(map).validPath(r.path, walked));
  }
}

TEST(SeedSearch, ToleranceLetsABranchNearTheGoalGoOn) {
  // Start and goal 2 apart in a straight line with a 1-cell pillar between them: limit 2, the shortest
  // way round needs 3 moves, allowed by the 3-cell tolerance in the first iteration.
  const mapio::OccupancyMap map = mapFromRows({".....", "..#..", "....."});
  SeedSearch s;
  const PlanResult r = s.plan(map, {1, 1}, {3, 1});
  ASSERT_TRUE(r.found());
  EXPECT_EQ(s.lastIterations(), 1);
  PlanOptions strict;
  strict.seedTolerance = 0;
  SeedSearch t;
  ASSERT_TRUE(t.plan(map, {1, 1}, {3, 1}, strict).found());
  EXPECT_EQ(t.lastIterations(), 2);
}

TEST(SeedSearch, FindsAPathInEveryAppendixARoomWheneverOneExists) {
  const std::string dir = std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/";
  for (const char* name : {"occupancy-089.map", "occupancy-120.map", "occupancy-139.map", "start-positions.map"}) {
    const mapio::MapLoad m = mapio::loadMap(dir + name);
    ASSERT_TRUE(m.map) << m.error;
    const Traversability grid(*m.map);
    SeedSearch seed;
    const MapCell from{1, 20};
    const std::vector<double> dist = distancesFrom(grid, from);
    int checked = 0;
    for (int r = 0; r < m.map->height(); r += 3) {
      for (int c = 0; c < m.map->width(); c += 3) {
        if (!grid.passable({c, r})) continue;
        const PlanResult p = seed.plan(grid, from, {c, r});
        ASSERT_EQ(p.found(), dist[grid.index({c, r})] < 1e18) << name << " to " << c << "," << r;
        if (p.found()) {
          EXPECT_GE(p.length, dist[grid.index({c, r})] - 1e-9);
        }
        ++checked;
      }
    }
    EXPECT_GT(checked, 20);
  }
}

}  // namespace
}  // namespace nxtmap::plan
