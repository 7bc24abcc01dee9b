#include "host/sim/WorldTruth.hpp"

#include <gtest/gtest.h>

namespace nxtmap::sim {
namespace {

// Left room (cols 1..4) is reachable; the pocket at cols 6..7 lies behind the wall at col 5.
const World& twoRooms() {
  static const World w = World::fromRows({"#########", "#....#..#", "#.#..#..#", "#....#..#", "#########"});
  return w;
}

bool at(const std::vector<uint8_t>& cells, const World& w, int c, int r) {
  return cells[static_cast<size_t>(r * w.width() + c)] != 0;
}

TEST(WorldTruth, ReachableAndObservableInTwoRooms) {
  const World& w = twoRooms();
  const Observability o = computeObservability(w, 1, 1, 3, 3);
  EXPECT_EQ(o.reachableCount, 11);
  EXPECT_TRUE(at(o.reachable, w, 4, 3));
  EXPECT_FALSE(at(o.reachable, w, 2, 2));   // obstacle
  EXPECT_FALSE(at(o.reachable, w, 6, 1));   // behind the wall
  EXPECT_TRUE(at(o.observable, w, 2, 2));   // obstacle seen
  EXPECT_TRUE(at(o.observable, w, 5, 2));   // dividing wall seen
  EXPECT_FALSE(at(o.observable, w, 6, 2));  // free pocket behind it
  EXPECT_FALSE(at(o.observable, w, 8, 2));  // outer wall behind the pocket
  EXPECT_FALSE(at(o.observable, w, 0, 0));  // corners are never on an axis from a free cell
  EXPECT_EQ(o.observableFree, 11);
  // Walls: 4 top + 4 bottom + 3 left + 3 divider + the obstacle.
  EXPECT_EQ(o.observableOccupied, 15);
}

TEST(WorldTruth, RangesOfZeroSeeNothingOfThatKind) {
  const World& w = twoRooms();
  const Observability noFree = computeObservability(w, 1, 1, 0, 3);
  EXPECT_EQ(noFree.observableFree, 0);
  EXPECT_EQ(noFree.observableOccupied, 15);
  const Observability noHits = computeObservability(w, 1, 1, 3, 0);
  EXPECT_EQ(noHits.observableFree, 11);
  EXPECT_EQ(noHits.observableOccupied, 0);
}

TEST(WorldTruth, RangeLimitsSightFromALoneCell) {
  // The start cell is shut in, so only sight lines from it count: the far obstacle is 3 cells away.
  const World w = World::fromRows({"#####", "#.#.#", "#####"});
  const Observability near = computeObservability(w, 1, 1, 5, 1);
  EXPECT_EQ(near.reachableCount, 1);
  EXPECT_EQ(near.observableFree, 0);  // the start cell is not observable by itself
  EXPECT_EQ(near.observableOccupied, 4);
  EXPECT_FALSE(at(near.observable, w, 3, 1));
  const World corridor = World::fromRows({"#.....#"});
  const Observability shortSight = computeObservability(corridor, 1, 0, 2, 1);
  EXPECT_EQ(shortSight.observableFree, 5);
  EXPECT_TRUE(at(shortSight.observable, corridor, 6, 0));
}

TEST(WorldTruth, ABlockedStartCellIsStoodInAndSeenFrom) {
  // A wall reaching a sliver into the start cell: the robot stands there all the same.
  const World w = World::fromRows({"#####", "#...#", "##..#", "#####"});
  const Observability o = computeObservability(w, 1, 2, 5, 5);
  EXPECT_EQ(o.reachableCount, 6);  // the start and the five free cells around it
  EXPECT_TRUE(at(o.reachable, w, 1, 2));
  EXPECT_TRUE(at(o.reachable, w, 3, 2));
  EXPECT_TRUE(at(o.observable, w, 1, 3));  // the wall below the start
  EXPECT_TRUE(at(o.observable, w, 0, 2));  // the wall to its left
  EXPECT_FALSE(at(o.observable, w, 0, 0));
  EXPECT_EQ(o.observableFree, 5);
  // The ring but its corners (3 above, 3 below, 2 left, 2 right); the start is stood in, not seen.
  EXPECT_EQ(o.observableOccupied, 10);
  EXPECT_FALSE(at(o.observable, w, 1, 2));
}

TEST(WorldTruth, AStartOutsideTheMapReachesNothing) {
  const Observability o = computeObservability(twoRooms(), -1, 0, 5, 5);
  EXPECT_EQ(o.reachableCount, 0);
  EXPECT_EQ(o.observableFree + o.observableOccupied, 0);
  EXPECT_EQ(o.reachable.size(), 45u);
  EXPECT_EQ(o.observable.size(), 45u);
}

}  // namespace
}  // namespace nxtmap::sim
