// The explorer of a body that turns only where the four cells around it are known free
// (ExplorerConfig::turnNeedsRoom), against a scripted robot in a map drawn as text: when nothing is left within
// reach by that rule, it tries once more turning anywhere (the pilot turns a turn that meets something back);
// where a turn with room is at hand, the rule holds.
#include <gtest/gtest.h>

#include "tests/explore/ScriptedRoom.hpp"

namespace nxtmap {
namespace {

TEST(RoomWaiver, WithNothingLeftInReachTurningWithRoomTheRobotTurnsWhereItMust) {
  // A corridor one cell wide opening onto a row one cell deep and 16 long: no cell has four free neighbours,
  // and the row's far ends lie beyond the sensors' 6 cells from the corridor's end.
  const TextWorld world({"##################", "#................#", "########.#########", "########.#########",
                         "########S#########", "##################"});
  ScriptedRun run;
  run.go(world);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_GE(run.turnsWithoutRoom, 1);
  // Both ends of the row are mapped: its end walls (8 and 9 cells from the corridor) are known.
  EXPECT_EQ(run.map.at(Cell{-8, 3}), CellState::Occupied);
  EXPECT_EQ(run.map.at(Cell{9, 3}), CellState::Occupied);
}

TEST(RoomWaiver, WhereATurnWithRoomIsAtHandTheRuleHolds) {
  // An open room: every turn can be made where the four cells around are free.
  const TextWorld world(
      {"##########", "#........#", "#........#", "#........#", "#...S....#", "#........#", "#........#", "##########"});
  ScriptedRun run;
  run.go(world);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_GE(run.turns, 1);
  EXPECT_EQ(run.turnsWithoutRoom, 0);
}

TEST(RoomWaiver, NoTurnIsTriedAgainWhereOneStalled) {
  const TextWorld world(
      {"##########", "#........#", "#........#", "#........#", "#...S....#", "#........#", "#........#", "##########"});
  ScriptedRun run;
  run.stallFirstTurn = true;
  run.go(world);
  ASSERT_TRUE(run.stalled);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_GE(run.turns, 1);
  EXPECT_EQ(run.turnsAtStalled, 0);
  EXPECT_EQ(run.explorer->counters().blockedMoves, 1u);
}

TEST(RoomWaiver, ATurnThatStalledIsTriedOnceMoreBeforeTheRobotGivesUp) {
  // The corridor of the first test: the turn into the row, the only way on, stalls the first time (the robot stood
  // a few mm off where a later try finds room). Before giving up with the row unknown, the robot turns there again.
  const TextWorld world({"##################", "#................#", "########.#########", "########.#########",
                         "########S#########", "##################"});
  ScriptedRun run;
  run.stallFirstTurn = true;
  run.go(world);
  ASSERT_TRUE(run.stalled);
  ASSERT_TRUE(run.explorer->finished());
  EXPECT_EQ(run.explorer->end(), ExplorerEnd::Complete);
  EXPECT_GE(run.turnsAtStalled, 1);
  EXPECT_EQ(run.map.at(Cell{-8, 3}), CellState::Occupied);
  EXPECT_EQ(run.map.at(Cell{9, 3}), CellState::Occupied);
}

}  // namespace
}  // namespace nxtmap
