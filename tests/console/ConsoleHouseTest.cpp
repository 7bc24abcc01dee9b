// The console's house through the stand-in brick (sim: link, SimBrick): rooms, save -> load -> save
// byte for byte, a new room reported by the brick, and the connect command with a house.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "host/console/Console.hpp"
#include "host/network/HouseFiles.hpp"
#include "tests/cli/CliTestSupport.hpp"
#include "tests/console/ConsoleHouseRig.hpp"

namespace nxtmap::console {
namespace {

using test::endsWith;
using test::Rig;
using test::savedHouse;
using test::twoRoomHouse;
using test::worldFile;

std::map<std::string, std::string> filesOf(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    out[e.path().filename().string()] = cli::test::readFile(e.path().string());
  }
  return out;
}

TEST(ConsoleHouse, RoomsListsTheHouseAndMarksTheCurrentRoom) {
  test::TempDir tmp("rooms");
  const network::HouseLoad house = savedHouse(tmp, "house");
  Rig rig(worldFile(tmp), &house);
  ASSERT_TRUE(rig.connected);
  ASSERT_TRUE(rig.settled()) << rig.log;
  const std::string out = rig.run("rooms");
  const std::vector<std::string> l = cli::test::lines(out);
  ASSERT_EQ(l.size(), 2u) << out;
  EXPECT_EQ(l[0],
            "room 0 hall (current): 8 x 7 cells from (-3,-3), 31 free, 25 occupied; robot at (0,0); "
            "exits: to room 1 at (4,0); labels: lamp (-2,2)");
  EXPECT_EQ(l[1],
            "room 1 kitchen: 7 x 9 cells from (-3,-1), 36 free, 26 occupied; exits: to room 0 at (0,-1); "
            "labels: fridge (-2,6)");
}

TEST(ConsoleHouse, SaveLoadSaveIsByteIdentical) {
  test::TempDir tmp("save");
  const network::HouseLoad house = savedHouse(tmp, "original");
  {
    Rig rig(worldFile(tmp), &house);
    ASSERT_TRUE(rig.connected);
    ASSERT_TRUE(rig.settled()) << rig.log;
    EXPECT_EQ(rig.run("save " + tmp.path("first")), "saved house " + tmp.path("first") + ": 2 rooms, 1 gateways\n");
  }
  const network::HouseLoad first = network::loadHouse(tmp.path("first"));
  ASSERT_TRUE(first.network.has_value()) << first.error;
  {
    Rig rig(worldFile(tmp), &first);
    ASSERT_TRUE(rig.connected);
    ASSERT_TRUE(rig.settled()) << rig.log;
    rig.run("save " + tmp.path("second"));
  }
  const auto a = filesOf(tmp.path("original")), b = filesOf(tmp.path("first")), c = filesOf(tmp.path("second"));
  EXPECT_EQ(a.size(), 5u);  // house.yaml, hall.yaml/pgm, kitchen.yaml/pgm
  EXPECT_EQ(a, b);
  EXPECT_EQ(b, c);
}

TEST(ConsoleHouse, ANewRoomFromTheBrickKeepsTheOldRoomAndRecordsTheGateway) {
  test::TempDir tmp("newroom");
  const network::HouseLoad house = savedHouse(tmp, "house");
  Rig rig(worldFile(tmp), &house);
  ASSERT_TRUE(rig.connected);
  ASSERT_TRUE(rig.settled()) << rig.log;
  // Drive into the doorway (hall (4,0) = map column 7, row 3), facing east, then press Left.
  rig.run("route 0 7 3");
  ASSERT_TRUE(endsWith(rig.run("wait goal 60"), "goal reached\n")) << rig.log;
  rig.transport->pressNewRoom();
  ASSERT_TRUE(rig.waitUntil([&] { return rig.console->currentRoom() == 2; }, 10)) << rig.log;
  EXPECT_NE(
      rig.log.find("the brick went into a new room: room 2 (brick room 1), joined to room 0 by a gateway at (4,0)"),
      std::string::npos)
      << rig.log;
  const network::HouseNetwork& h = rig.console->house();
  ASSERT_EQ(h.rooms().size(), 3u);
  EXPECT_EQ(h.rooms()[0].map, twoRoomHouse().rooms()[0].map);  // the hall is kept as it was
  // The new room's frame starts in the doorway, +y east: its (0,1) is world (8,3) = hall (5,0).
  EXPECT_EQ(h.rooms()[2].toHouse.apply(Cell{0, 1}), (Cell{5, 0}));
  ASSERT_EQ(h.gateways().size(), 2u);
  EXPECT_EQ(h.gateways()[1].cellsA, (std::vector<Cell>{Cell{4, 0}}));
  EXPECT_EQ(h.gateways()[1].cellsB, (std::vector<Cell>{Cell{0, 0}}));
  // Explore a little of the new room, then save: the house loads back with all three rooms.
  rig.run("explore");
  EXPECT_TRUE(
      rig.waitUntil([&] { return rig.runner->with([](link::Session& s) { return s.map().known() > 20; }); }, 30));
  rig.run("stop");
  EXPECT_NE(rig.run("save " + tmp.path("after")).find("3 rooms, 2 gateways"), std::string::npos);
  const network::HouseLoad again = network::loadHouse(tmp.path("after"));
  ASSERT_TRUE(again.network.has_value()) << again.error;
  EXPECT_EQ(again.network->rooms()[2].name, "room2");
  EXPECT_GT(again.network->rooms()[2].map.count(CellState::Free), 5);
}

TEST(ConsoleHouse, TheConnectCommandLoadsAHouseAndDrivesARouteFromAScript) {
  test::TempDir tmp("cli");
  const std::string world = worldFile(tmp);
  savedHouse(tmp, "house");
  tmp.write("script",
            "rooms\nroute kitchen 5 2\nwait goal 60\nlabel stove 3 3\nsave " + tmp.path("saved") + "\nquit\n");
  const std::string cmd = "cd " + cli::test::shellQuote(NXTMAP_SOURCE_DIR) + " && " +
                          cli::test::shellQuote(NXTMAP_CLI_PATH) + " connect sim:" + world +
                          "@3,3 --speed 20 --house " + tmp.path("house") + " < " + tmp.path("script") + " > " +
                          tmp.path("out") + " 2> " + tmp.path("err");
  const int status = std::system(cmd.c_str());
  const std::string out = cli::test::readFile(tmp.path("out"));
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0) << cli::test::readFile(tmp.path("err"));
  EXPECT_EQ(cli::test::readFile(tmp.path("err")), "");
  EXPECT_NE(
      out.find("house: 2 rooms, 1 gateways; the brick is in room 0 (hall): its map (8 x 7 cells) goes to the brick"),
      std::string::npos)
      << out;
  EXPECT_NE(out.find("room 0 hall (current)"), std::string::npos) << out;
  EXPECT_NE(out.find("route done: the robot is at (2,5) in room 1"), std::string::npos) << out;
  EXPECT_NE(out.find("saved house " + tmp.path("saved") + ": 2 rooms, 1 gateways"), std::string::npos) << out;
  // The label went to the kitchen (the current room), in the kitchen's frame: column 3, row 3 = (0, 4).
  const network::HouseLoad saved = network::loadHouse(tmp.path("saved"));
  ASSERT_TRUE(saved.network.has_value()) << saved.error;
  EXPECT_EQ(saved.network->rooms()[1].labels.at("stove"), (Cell{0, 4}));
  EXPECT_EQ(saved.network->rooms()[0].labels.at("lamp"), (Cell{-2, 2}));
}

TEST(ConsoleHouse, ABadHouseOrRoomIsOneClearErrorBeforeConnecting) {
  test::TempDir tmp("badhouse");
  const std::string world = worldFile(tmp);
  savedHouse(tmp, "house");
  std::filesystem::create_directories(tmp.path("empty"));
  struct Case {
    std::string args, start;
  };
  const Case cases[] = {
      {"--house " + tmp.path("none"), "nxtmap: connect: --house " + tmp.path("none") + ": "},
      {"--house " + tmp.path("empty"), "nxtmap: connect: --house " + tmp.path("empty") + ": "},
      {"--house " + tmp.path("house") + " --room 2",
       "nxtmap: connect: --room 2: the house " + tmp.path("house") + " has rooms 0..1"},
      {"--room 1", "nxtmap: connect: --room needs --house DIR"},
  };
  for (const Case& c : cases) {
    const std::string cmd = "cd " + cli::test::shellQuote(NXTMAP_SOURCE_DIR) + " && " +
                            cli::test::shellQuote(NXTMAP_CLI_PATH) + " connect sim:" + world + "@3,3 " + c.args +
                            " < /dev/null > " + tmp.path("out") + " 2> " + tmp.path("err");
    const int status = std::system(cmd.c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2) << c.args;
    const std::vector<std::string> err = cli::test::lines(cli::test::readFile(tmp.path("err")));
    ASSERT_EQ(err.size(), 1u) << c.args;
    EXPECT_EQ(err[0].rfind(c.start, 0), 0u) << err[0];
    EXPECT_EQ(cli::test::readFile(tmp.path("out")), "") << c.args;
  }
}

}  // namespace
}  // namespace nxtmap::console
