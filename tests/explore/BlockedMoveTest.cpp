// The explorer when a move is blocked (the pilot's drive stalled and went back where it started): a cell the
// robot never stood in becomes a wall at once; one it stood in, blocked once, stays free (a body that grazes a
// wall beside its way is blocked too, and a cell it drove through made a wall cuts its map in two), a second time
// it is a wall.
#include <gtest/gtest.h>

#include "tests/explore/ScriptedRoom.hpp"

namespace nxtmap {
namespace {

// Cells the world has free that the map calls occupied.
int wrongWalls(const ScriptedRun& run, const TextWorld& world) {
  int n = 0;
  for (int16_t y = -10; y <= 10; ++y)
    for (int16_t x = -10; x <= 10; ++x)
      n += !world.blocked(Cell{x, y}) && run.map.at(Cell{x, y}) == CellState::Occupied ? 1 : 0;
  return n;
}

const TextWorld kRoom({"##########", "#........#", "#........#", "#........#", "#...S....#", "#........#", "#........#",
                       "##########"});

TEST(BlockedMove, ACellTheRobotStoodInBlockedOnceStaysFree) {
  ScriptedRun run;
  run.grazes = 1;
  run.go(kRoom);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_EQ(run.grazes, 0) << "a move back was blocked";
  EXPECT_EQ(run.explorer->counters().blockedMoves, 1u);
  EXPECT_EQ(wrongWalls(run, kRoom), 0);
  EXPECT_EQ(run.map.grid().count(CellState::Free), 48) << "the whole room";
}

TEST(BlockedMove, EveryMoveBackBlockedStillEnds) {
  // Every move back into a cell stood in is blocked: each such cell becomes a wall at its second blocked move
  // (MapLayers.ABlockedMoveIsCertainUnlessTheCellIsSurelyFree), so the explorer does not try it for ever and ends.
  ScriptedRun run;
  run.grazes = 1000;
  run.go(kRoom);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_GE(run.explorer->counters().blockedMoves, 2u);
  EXPECT_LT(run.explorer->counters().blockedMoves, 200u);
}

}  // namespace
}  // namespace nxtmap
