// `explore house` keeps, for each room the brick maps, the cells its statuses put it in: the house cuts the room
// out of the brick's map from them as well as from its start (host/house/RoomCut). Only statuses of the room being
// mapped, while the brick explores it, count.
#include <gtest/gtest.h>

#include <vector>

#include "tests/console/HouseByPacket.hpp"

namespace nxtmap::console {
namespace {

using protocol::BrickMode;
using HouseStoodTest = test::HouseByPacket;

TEST_F(HouseStoodTest, TheCellsOfTheRoomsStatusesWhileItIsExploredAreKeptEachOnceInARow) {
  struct Row {
    BrickMode mode;
    Cell at;
    uint16_t room;
  };
  const std::vector<Row> statuses = {
      {BrickMode::Exploring, Cell{0, 1}, 2},  {BrickMode::Exploring, Cell{0, 1}, 2},
      {BrickMode::Exploring, Cell{0, 2}, 2},  {BrickMode::Exploring, Cell{9, 9}, 7},  // another room's
      {BrickMode::Idle, Cell{5, 5}, 2},       {BrickMode::Following, Cell{6, 6}, 2},  // not exploring
      {BrickMode::Exploring, Cell{-3, 2}, 2}, {BrickMode::Exploring, Cell{0, 2}, 2},
  };
  double t = 1.0;
  for (const Row& r : statuses) status(r.mode, t += 0.5, r.at, r.room);
  const std::vector<Cell> expected = {Cell{0, 1}, Cell{0, 2}, Cell{-3, 2}, Cell{0, 2}};
  EXPECT_EQ(house.stoodInRoom(), expected);
}

}  // namespace
}  // namespace nxtmap::console
