// Labels as goals: the closest reachable passable cell next to a labelled block ("go near the chair").
#include <gtest/gtest.h>

#include "host/plan/NearGoal.hpp"
#include "tests/plan/PlanTestSupport.hpp"

namespace nxtmap::plan {
namespace {

using test::mapFromRows;

TEST(NearGoal, ClosestReachableCellNextToTheBlock) {
  const mapio::OccupancyMap map = mapFromRows({
      "..........",
      "..........",
      ".....##...",
      ".....##...",
      "..........",
  });
  const Traversability grid(map);
  const mapio::CellBlock chair{5, 2, 2, 2};
  // From the left, the nearest neighbour of the chair is on its left side.
  EXPECT_EQ(nearestCellNextTo(grid, {0, 2}, chair), (MapCell{4, 2}));
  // From the right.
  EXPECT_EQ(nearestCellNextTo(grid, {9, 3}, chair), (MapCell{7, 3}));
  // Already next to it: stay.
  EXPECT_EQ(nearestCellNextTo(grid, {6, 4}, chair), (MapCell{6, 4}));
  // A label on free cells: the neighbours still count, the block's own cells do not.
  EXPECT_EQ(nearestCellNextTo(grid, {0, 0}, mapio::CellBlock{2, 0, 1, 1}), (MapCell{1, 0}));
}

TEST(NearGoal, NothingReachableNextToIt) {
  const mapio::OccupancyMap map = mapFromRows({
      "...#...",
      "...#.#.",
      "...#...",
  });
  const Traversability grid(map);
  EXPECT_FALSE(nearestCellNextTo(grid, {0, 0}, mapio::CellBlock{5, 1, 1, 1}));
  EXPECT_TRUE(nearestCellNextTo(grid, {6, 0}, mapio::CellBlock{5, 1, 1, 1}));
  EXPECT_FALSE(nearestCellNextTo(grid, {3, 0}, mapio::CellBlock{5, 1, 1, 1}));  // start not passable
}

}  // namespace
}  // namespace nxtmap::plan
