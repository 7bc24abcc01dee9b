// The console's routes across the house through the stand-in brick (sim: link, SimBrick): a route across
// rooms uploads each room's map with the robot's pose in it and the robot really crosses; refused routes
// send nothing.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "host/console/Console.hpp"
#include "tests/console/ConsoleHouseRig.hpp"

namespace nxtmap::console {
namespace {

using test::endsWith;
using test::kStartCol;
using test::kStartRow;
using test::Rig;
using test::savedHouse;
using test::twoRoomHouse;
using test::worldFile;

TEST(ConsoleHouse, ARouteAcrossTwoRoomsUploadsTheFarRoomWithThePoseAndReachesTheGoal) {
  test::TempDir tmp("route");
  const network::HouseLoad house = savedHouse(tmp, "house");
  Rig rig(worldFile(tmp), &house);
  ASSERT_TRUE(rig.connected);
  EXPECT_NE(rig.entered.find("the brick is in room 0 (hall)"), std::string::npos) << rig.entered;
  ASSERT_TRUE(rig.settled()) << rig.log;
  // Goal: world (13, 5) = kitchen cell (2, 5) = kitchen map column 2 - (-3) = 5, row 7 - 5 = 2.
  const std::string out = rig.run("route kitchen 5 2");
  EXPECT_NE(out.find("rooms 0 -> 1; gateways (4,0) in room 0 = (0,-1) in room 1"), std::string::npos) << out;
  EXPECT_NE(out.find("driving to leg 1 of 2 in room 0"), std::string::npos) << out;
  EXPECT_TRUE(endsWith(rig.run("wait goal 60"), "goal reached\n")) << rig.log;
  EXPECT_NE(rig.log.find("at the gateway: room 1 (kitchen) goes to the brick, the robot stands at (0,-1) there"),
            std::string::npos)
      << rig.log;
  EXPECT_NE(rig.log.find("route done: the robot is at (2,5) in room 1"), std::string::npos) << rig.log;
  EXPECT_EQ(rig.console->currentRoom(), 1);
  // The live map is the kitchen as uploaded (the brick took it in the kitchen's frame).
  EXPECT_TRUE(
      rig.waitUntil([&] { return rig.console->snapshot().rooms()[1].map == twoRoomHouse().rooms()[1].map; }, 10));
  // A route back to the hall by label.
  EXPECT_NE(rig.run("route near lamp").find("rooms 1 -> 0"), std::string::npos) << rig.log;
  EXPECT_TRUE(endsWith(rig.run("wait goal 60"), "goal reached\n")) << rig.log;
  rig.runner->stop();
  const link::SimBrick& brick = rig.transport->brick();
  EXPECT_EQ(rig.console->currentRoom(), 0);
  int col = 0, row = 0;
  brick.trueCell(col, row);
  // Next to the lamp at hall (-2, 2) = world (1, 1): a free neighbour.
  EXPECT_LE(std::abs(col - 1), 1);
  EXPECT_LE(std::abs(row - 1), 1);
  EXPECT_FALSE(col == 1 && row == 1);
  EXPECT_EQ(brick.mapChunks(), 3u);  // hall at the start, kitchen, hall again (one chunk each)
}

TEST(ConsoleHouse, TheRobotReallyCrossesIntoTheFarRoom) {
  test::TempDir tmp("cross");
  const network::HouseLoad house = savedHouse(tmp, "house");
  Rig rig(worldFile(tmp), &house);
  ASSERT_TRUE(rig.connected);
  ASSERT_TRUE(rig.settled()) << rig.log;
  rig.run("route 1 5 2");
  EXPECT_TRUE(endsWith(rig.run("wait goal 60"), "goal reached\n")) << rig.log;
  rig.runner->stop();
  const link::SimBrick& brick = rig.transport->brick();
  int col = 0, row = 0;
  brick.trueCell(col, row);
  EXPECT_EQ(col, 13);
  EXPECT_EQ(row, 5);
  EXPECT_EQ(brick.pose().cell, (Cell{2, 5}));                    // in the kitchen's frame
  EXPECT_EQ(brick.grid().at(Cell{-3, 7}), CellState::Occupied);  // the kitchen's map is the brick's now
  EXPECT_EQ(brick.grid().at(Cell{3, 7}), CellState::Unknown);
}

TEST(ConsoleHouse, BadRoutesAreRefusedWithOneMessageAndNothingIsSent) {
  test::TempDir tmp("bad");
  const network::HouseLoad house = savedHouse(tmp, "house", true);
  Rig rig(worldFile(tmp), &house);
  ASSERT_TRUE(rig.connected);
  ASSERT_TRUE(rig.settled()) << rig.log;
  struct Case {
    std::string line, message;
  };
  const Case cases[] = {
      {"route 7 1 1", "route 7 1 1: no room '7' (the house has rooms 0..2, see rooms); nothing sent"},
      {"route pantry 1 1", "route pantry 1 1: no room 'pantry' (the house has rooms 0..2, see rooms); nothing sent"},
      {"route 1 99 99", "route 1 99 99: outside room 1's map (7 x 9 cells); nothing sent"},
      {"route 1 0 0", "route 1 0 0: that cell is an obstacle; nothing sent"},
      {"route 1 6 0", "route 1 6 0: that cell is unexplored; nothing sent"},
      {"route attic 5 2", "route attic 5 2: no gateways lead from hall to attic; nothing sent"},
      {"route near sofa", "route near sofa: no room has the label 'sofa'; nothing sent"},
  };
  const uint64_t sent = rig.commandsSent();
  for (const Case& c : cases) {
    try {
      rig.run(c.line);
      ADD_FAILURE() << c.line << " was accepted";
    } catch (const ConsoleError& e) {
      EXPECT_EQ(std::string(e.what()), c.message);
    }
  }
  for (const char* malformed : {"route", "route 1 2", "route 1 a b", "route near"}) {
    EXPECT_THROW(parseConsoleCommand(malformed), ConsoleError) << malformed;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(rig.commandsSent(), sent);
  rig.runner->stop();
  int col = 0, row = 0;
  rig.transport->brick().trueCell(col, row);
  EXPECT_EQ(col, kStartCol);
  EXPECT_EQ(row, kStartRow);
}

}  // namespace
}  // namespace nxtmap::console
