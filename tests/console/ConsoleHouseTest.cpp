// The console's house through the stand-in brick (sim: link, SimBrick): routes across rooms that
// upload each room's map with the robot's pose in it, refused routes that send nothing, rooms,
// save -> load -> save byte for byte, and a new room reported by the brick.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "host/console/Console.hpp"
#include "host/link/SimTransport.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/network/HouseFiles.hpp"
#include "tests/cli/CliTestSupport.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::console {
namespace {

using network::RoomMap;

// Two rooms joined by a one-cell doorway at world (7, 3). The robot starts at (3, 3) facing up.
const char* kWorldRows[] = {
    "################", "#......#.......#", "#......#.......#", "#..............#",
    "#......#.......#", "#......#.......#", "################",
};
constexpr int kStartCol = 3, kStartRow = 3;

std::string worldFile(const test::TempDir& tmp) {
  std::string text = "type octile\nheight 7\nwidth 16\nmap\n";
  for (const char* r : kWorldRows) text += std::string(r) + "\n";
  for (char& c : text)
    if (c == '#') c = '@';
  return tmp.write("two-rooms.map", text);
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool worldBlocked(int col, int row) {
  return col < 0 || row < 0 || row >= 7 || col >= 16 || kWorldRows[row][col] == '#';
}

// The room's map from the world's truth over a box of its frame.
RoomMap truthMap(const mapping::FrameTransform& f, int minX, int minY, int w, int h) {
  RoomMap m(minX, minY, w, h);
  for (int y = minY; y < minY + h; ++y) {
    for (int x = minX; x < minX + w; ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      int col = 0, row = 0;
      f.toWorld(c, col, row);
      m.set(c, worldBlocked(col, row) ? CellState::Occupied : CellState::Free);
    }
  }
  return m;
}

// Room 0: frame at the start (3,3) facing up (north); room 1: frame at (8,3) facing east, so the
// two frames are a quarter turn apart. Gateway: the doorway, (4,0) in room 0 = (0,-1) in room 1.
// Room 2 (optional) is a copy of room 1 with no gateway: unreachable.
network::HouseNetwork twoRoomHouse(bool withIsland = false) {
  const mapping::FrameTransform f0(kStartCol, kStartRow, sim::Heading::N), f1(8, 3, sim::Heading::E);
  network::HouseNetwork h;
  network::RoomNode r0;
  r0.name = "hall";
  r0.map = truthMap(f0, -3, -3, 8, 7);  // world cols 0..7, rows 0..6
  r0.labels["lamp"] = Cell{-2, 2};
  h.addRoom(r0);
  network::RoomNode r1;
  r1.name = "kitchen";
  r1.map = truthMap(f1, -3, -1, 7, 9);         // world cols 7..15, rows 0..6
  r1.map.set(Cell{3, 7}, CellState::Unknown);  // world (15, 6): a corner nobody saw
  r1.labels["fridge"] = Cell{-2, 6};           // world (14, 1)
  r1.toHouse = network::RoomTransform::fromPose(f0.toExplorer(8, 3), Dir::East);
  h.addRoom(r1);
  network::Gateway g;
  g.roomA = 0;
  g.roomB = 1;
  g.cellsA = {f0.toExplorer(7, 3)};
  g.cellsB = {f1.toExplorer(7, 3)};
  h.addGateway(g);
  if (withIsland) {
    network::RoomNode r2 = r1;
    r2.name = "attic";
    r2.labels.clear();
    h.addRoom(r2);
  }
  return h;
}

// A console on the stand-in brick in the two-room world, with the house loaded (brick in room 0).
struct Rig {
  explicit Rig(const std::string& world, const network::HouseLoad* house = nullptr) {
    transport = std::make_shared<link::SimTransport>(
        link::parseLinkSpec("sim:" + world + "@" + std::to_string(kStartCol) + "," + std::to_string(kStartRow)), 20.0);
    std::shared_ptr<link::SimTransport> t = transport;
    runner = std::make_unique<link::LinkRunner>(
        [t]() -> std::unique_ptr<link::Transport> {
          struct Proxy : link::Transport {
            std::shared_ptr<link::SimTransport> t;
            size_t read(uint8_t* b, size_t c, int ms) override { return t->read(b, c, ms); }
            void write(const uint8_t* d, size_t n) override { t->write(d, n); }
            std::string describe() const override { return t->describe(); }
          };
          auto p = std::make_unique<Proxy>();
          p->t = t;
          return p;
        },
        link::SessionConfig{});
    runner->start();
    console = std::make_unique<Console>(*runner, "sim");
    if (house) console->useHouse(*house->network, house->resolutionM, 0);
    connected = waitUntil([&] { return runner->with([](link::Session& s) { return s.connected(); }); }, 20);
    if (connected && house) entered = console->enterHouseRoom();
  }
  ~Rig() { runner->stop(); }
  template <class F>
  bool waitUntil(F done, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
      if (done()) return true;
      log += console ? console->poll() : "";
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return done();
  }
  std::string run(const std::string& line) {
    const std::string out = console->execute(parseConsoleCommand(line));
    log += out;
    return out;
  }
  // The brick holds room 0 as uploaded: its map came back (live) and the robot stands at (0,0).
  bool settled() {
    return waitUntil(
        [&] {
          return runner->with([](link::Session& s) {
            return s.commandsDone() && s.pose().has_value() && s.map().known() > 0;
          }) && console->snapshot().rooms()[0].map == twoRoomHouse().rooms()[0].map;
        },
        20);
  }
  uint64_t commandsSent() {
    return runner->with([](link::Session& s) { return s.counters().commandsSent; });
  }

  std::shared_ptr<link::SimTransport> transport;
  std::unique_ptr<link::LinkRunner> runner;
  std::unique_ptr<Console> console;
  bool connected = false;
  std::string entered, log;
};

network::HouseLoad savedHouse(const test::TempDir& tmp, const std::string& name, bool withIsland = false) {
  std::string error;
  EXPECT_TRUE(network::saveHouse(twoRoomHouse(withIsland), 0.10, tmp.path(name), error)) << error;
  network::HouseLoad load = network::loadHouse(tmp.path(name));
  EXPECT_TRUE(load.network.has_value()) << load.error;
  return load;
}

std::map<std::string, std::string> filesOf(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    out[e.path().filename().string()] = cli::test::readFile(e.path().string());
  }
  return out;
}

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
