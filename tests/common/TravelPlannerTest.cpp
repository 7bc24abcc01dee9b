#include <gtest/gtest.h>

#include "common/explore/TravelPlanner.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

struct PlanCase {
  const char* name;
  std::vector<std::string> rows;  // (0,0) = bottom-left cell
  Pose from;
  Cell to;
  int cost;  // moves + quarter turns; -1 = unreachable
};

TEST(TravelPlanner, CostsCountMovesAndTurns) {
  const std::vector<PlanCase> cases = {
      {"straight ahead", {"....."}, {{0, 0}, Dir::East}, {4, 0}, 4},
      {"straight behind: drives backwards, no turn", {"....."}, {{4, 0}, Dir::East}, {0, 0}, 4},
      {"one corner: one turn", {"....", "....", "...."}, {{0, 0}, Dir::North}, {3, 2}, 6},
      {"start on the wrong axis", {"....."}, {{0, 0}, Dir::North}, {3, 0}, 4},
      {"around a wall", {"...", ".#.", ".#.", ".#."}, {{0, 0}, Dir::North}, {2, 0}, 10},
      {"walled off", {".#."}, {{0, 0}, Dir::North}, {2, 0}, -1},
      {"start is goal", {"."}, {{0, 0}, Dir::North}, {0, 0}, 0},
  };
  for (const PlanCase& c : cases) {
    test::GridFixture f;
    f.draw(c.rows);
    TravelStorage<32, 32, 512> storage;
    TravelPlanner planner(storage.view(), 32, 32);
    int found = -1;
    ASSERT_TRUE(planner.search(f.grid(), c.from, [&](Cell cell, uint16_t cost) {
      if (cell == c.to) found = cost;
      return cell == c.to;
    })) << c.name;
    EXPECT_EQ(found, c.cost) << c.name;
    if (found > 0) {
      Route route;
      ASSERT_TRUE(planner.routeTo(f.grid(), c.to, static_cast<uint16_t>(found), route)) << c.name;
      Cell at = c.from.cell;
      while (!route.empty()) {
        at = advance(at, route.front());
        EXPECT_TRUE(f.grid().isFree(at)) << c.name;
        route.pop();
      }
      EXPECT_EQ(at, c.to) << c.name;
    }
  }
}

TEST(TravelPlanner, ReportsQueueOverflowInsteadOfOverrunning) {
  test::GridFixture f;
  f.draw({"..........", "..........", "..........", "..........", ".........."});
  TravelStorage<32, 32, 4> storage;
  TravelPlanner planner(storage.view(), 32, 32);
  EXPECT_FALSE(planner.search(f.grid(), Pose{{0, 0}, Dir::North}, [](Cell, uint16_t) { return false; }));
}

}  // namespace
}  // namespace nxtmap
