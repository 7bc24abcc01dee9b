// Planners on small grids with known answers: lengths, no path, start = goal, invalid ends, corner cutting,
// unknown cells, clearance.
#include <gtest/gtest.h>

#include <cmath>

#include "host/plan/Planner.hpp"
#include "tests/plan/PlanTestSupport.hpp"

namespace nxtmap::plan {
namespace {

using test::mapFromRows;

const Algorithm kAll[] = {Algorithm::AStar, Algorithm::Jps, Algorithm::Dijkstra, Algorithm::Seed};
const Algorithm kOptimal[] = {Algorithm::AStar, Algorithm::Jps, Algorithm::Dijkstra};

struct KnownCase {
  const char* name;
  std::vector<std::string> rows;
  MapCell from, to;
  double length;  // < 0: no path
};

const double s2 = std::sqrt(2.0);

const std::vector<KnownCase> kKnown = {
    {"straight", {"......"}, {0, 0}, {5, 0}, 5.0},
    {"diagonal", {"....", "....", "....", "...."}, {0, 0}, {3, 3}, 3 * s2},
    {"octile", {"......", "......", "......"}, {0, 0}, {5, 2}, 3 + 2 * s2},
    {"wall with gap", {"..#...", "..#...", "......"}, {0, 0}, {5, 0}, 3 + 3 * s2},
    {"no corner cutting", {".#", "#."}, {0, 0}, {1, 1}, -1},
    {"one corner blocked", {"..", "#."}, {0, 0}, {1, 1}, 2.0},
    {"walled in", {".#...", "##...", "....."}, {0, 0}, {4, 2}, -1},
    {"u-turn", {".....", ".###.", ".#.#.", ".#.#.", "....."}, {2, 2}, {2, 0}, 10.0},
    {"pocket", {".....", ".###.", ".#.#.", ".###.", "....."}, {2, 2}, {2, 0}, -1},
    {"detour", {"...#...", ".#.#.#.", ".#.#.#.", ".#...#."}, {0, 0}, {6, 0}, 12.0},
    {"unknown blocks", {"..?..", "..?..", "..?.."}, {0, 1}, {4, 1}, -1},
};

TEST(Planners, KnownAnswersOnSmallGrids) {
  for (const KnownCase& k : kKnown) {
    const mapio::OccupancyMap map = mapFromRows(k.rows);
    const Traversability grid(map);
    for (Algorithm a : kAll) {
      auto planner = makePlanner(a);
      const PlanResult r = planner->plan(map, k.from, k.to);
      const std::string what = std::string(k.name) + " / " + algorithmName(a);
      if (k.length < 0) {
        EXPECT_EQ(r.status, PlanStatus::NoPath) << what;
        EXPECT_TRUE(r.path.empty()) << what;
        continue;
      }
      ASSERT_EQ(r.status, PlanStatus::Found) << what;
      double walked = 0;
      ASSERT_TRUE(grid.validPath(r.path, walked)) << what;
      EXPECT_EQ(r.path.front(), k.from) << what;
      EXPECT_EQ(r.path.back(), k.to) << what;
      EXPECT_NEAR(walked, r.length, 1e-9) << what;
      if (a != Algorithm::Seed) {
        EXPECT_NEAR(r.length, k.length, 1e-9) << what;
      } else {
        EXPECT_GE(r.length, k.length - 1e-9) << what;
      }
      EXPECT_GT(r.nodesExpanded, 0u) << what;
    }
  }
}

TEST(Planners, StartEqualsGoalIsAOneCellPath) {
  const mapio::OccupancyMap map = mapFromRows({"...", "...", "..."});
  for (Algorithm a : kAll) {
    const PlanResult r = makePlanner(a)->plan(map, {1, 1}, {1, 1});
    ASSERT_EQ(r.status, PlanStatus::Found) << algorithmName(a);
    ASSERT_EQ(r.path.size(), 1u);
    EXPECT_EQ(r.path[0], (MapCell{1, 1}));
    EXPECT_EQ(r.length, 0.0);
  }
}

TEST(Planners, InvalidEndsAreReported) {
  const mapio::OccupancyMap map = mapFromRows({"..#", ".?.", "..."});
  for (Algorithm a : kAll) {
    auto p = makePlanner(a);
    EXPECT_EQ(p->plan(map, {-1, 0}, {0, 0}).status, PlanStatus::StartInvalid);
    EXPECT_EQ(p->plan(map, {2, 0}, {0, 0}).status, PlanStatus::StartInvalid);
    EXPECT_EQ(p->plan(map, {1, 1}, {0, 0}).status, PlanStatus::StartInvalid);
    EXPECT_EQ(p->plan(map, {0, 0}, {3, 0}).status, PlanStatus::GoalInvalid);
    EXPECT_EQ(p->plan(map, {0, 0}, {0, 3}).status, PlanStatus::GoalInvalid);
    EXPECT_EQ(p->plan(map, {0, 0}, {2, 0}).status, PlanStatus::GoalInvalid);
    EXPECT_EQ(p->plan(map, {0, 0}, {1, 1}).status, PlanStatus::GoalInvalid);
  }
}

TEST(Planners, UnknownCellsOnlyWhenAllowed) {
  const mapio::OccupancyMap map = mapFromRows({".?.", ".?.", ".?."});
  PlanOptions through;
  through.unknownTraversable = true;
  for (Algorithm a : kAll) {
    auto p = makePlanner(a);
    EXPECT_EQ(p->plan(map, {0, 1}, {2, 1}).status, PlanStatus::NoPath) << algorithmName(a);
    const PlanResult r = p->plan(map, {0, 1}, {2, 1}, through);
    ASSERT_TRUE(r.found()) << algorithmName(a);
    if (a != Algorithm::Seed) {
      EXPECT_NEAR(r.length, 2.0, 1e-9);
    }
  }
}

TEST(Planners, ClearanceKeepsAwayFromObstacles) {
  // A 1-cell gap in a wall: usable without clearance (entered straight: no corner cutting), closed with
  // clearance 1; row 1 keeps its clearance and stays usable.
  const mapio::OccupancyMap map = mapFromRows({
      ".........",
      ".........",
      ".........",
      "####.####",
      ".........",
      ".........",
      ".........",
  });
  PlanOptions clear1;
  clear1.clearanceCells = 1;
  for (Algorithm a : kOptimal) {
    auto p = makePlanner(a);
    const PlanResult r0 = p->plan(map, {1, 1}, {1, 5});
    ASSERT_TRUE(r0.found());
    EXPECT_NEAR(r0.length, 6 + 2 * std::sqrt(2.0), 1e-9) << algorithmName(a);
    EXPECT_EQ(p->plan(map, {1, 1}, {1, 5}, clear1).status, PlanStatus::NoPath) << algorithmName(a);
    // The start itself is too close to the map's edge with clearance 1.
    EXPECT_EQ(p->plan(map, {0, 0}, {1, 1}, clear1).status, PlanStatus::StartInvalid);
    const PlanResult r1 = p->plan(map, {1, 1}, {7, 1}, clear1);
    ASSERT_TRUE(r1.found());
    EXPECT_NEAR(r1.length, 6.0, 1e-9);
  }
}

TEST(Planners, NodeLimitStopsTheSearch) {
  const mapio::OccupancyMap map = mapFromRows({std::string(60, '.'), std::string(60, '.')});
  PlanOptions small;
  small.maxNodes = 1;
  for (Algorithm a : kAll) {
    EXPECT_EQ(makePlanner(a)->plan(map, {0, 0}, {59, 1}, small).status, PlanStatus::NodeLimit) << algorithmName(a);
  }
}

TEST(Planners, NamesRoundTrip) {
  for (Algorithm a : kAll) EXPECT_EQ(algorithmByName(algorithmName(a)), a);
  EXPECT_FALSE(algorithmByName("bfs"));
  EXPECT_EQ(makePlanner(Algorithm::Jps)->algorithm(), Algorithm::Jps);
}

}  // namespace
}  // namespace nxtmap::plan
