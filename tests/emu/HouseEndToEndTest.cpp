// Mapping a house end to end through the emulated brick: the real firmware (nxtmap-sim.elf, the
// simulator's 10 cm cells) runs in the emulated brick behind a loopback TCP link, and the PC console
// (its LinkRunner and Console, as `nxtmap connect` builds them) types `explore house`, then
// `wait house SECONDS` and `rooms`. No button is ever pressed: the brick maps each room confined
// (house commands Explore{confine}, GoTo, EnterRoom) and the console's house planner joins them.
// The world is three rooms in a row, written by the test: 30 x 14 cells, walls at x = 10 and
// x = 20 with doorways at rows 5..8 and 3..6; the robot starts at column 5, row 6 facing north.
#include "EmuTestSupport.hpp"
#include "host/console/Console.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/link/LinkRunner.hpp"
#include "host/link/LinkSpec.hpp"
#include "host/link/Transport.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR

constexpr int kWidth = 30, kHeight = 14;
constexpr int kSmallestRoomCells = 8 * 12;  // free cells of the smallest room's truth (x 21..28, rows 1..12)
constexpr double kWaitHouseS = 150.0;       // wall seconds the console waits

// The three-room world as an octile .map: '@' walls, '.' free.
std::string threeRoomMap() {
  std::ostringstream out;
  out << "type octile\nheight " << kHeight << "\nwidth " << kWidth << "\nmap\n";
  for (int row = 0; row < kHeight; ++row) {
    for (int col = 0; col < kWidth; ++col) {
      const bool outer = row == 0 || col == 0 || row == kHeight - 1 || col == kWidth - 1;
      const bool first = col == 10 && !(row >= 5 && row <= 8);
      const bool second = col == 20 && !(row >= 3 && row <= 6);
      out << (outer || first || second ? '@' : '.');
    }
    out << '\n';
  }
  return out.str();
}

struct HouseRun {
  bool connected = false;
  std::string waitAnswer, roomsText;
  network::HouseNetwork house;
  EmulatedRunReport brick;
  double wallSeconds = 0.0;
};

// The console side: connects, explores the house, waits for it and lists the rooms.
void driveConsole(int port, HouseRun& out) {
  const link::LinkSpec spec = link::parseLinkSpec("tcp:127.0.0.1:" + std::to_string(port));
  link::LinkRunner runner([spec](const link::WaitLimit& limit) { return link::openTransport(spec, limit); },
                          link::SessionConfig{}, 200, 5000);
  runner.start();
  console::Console console(runner, "tcp:127.0.0.1:" + std::to_string(port));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!(out.connected = runner.with([](link::Session& s) { return s.connected(); })) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (out.connected) {
    try {
      console.execute(console::parseConsoleCommand("explore house"));
      std::ostringstream wait;
      wait << "wait house " << kWaitHouseS;
      out.waitAnswer = console.execute(console::parseConsoleCommand(wait.str()));
      out.roomsText = console.execute(console::parseConsoleCommand("rooms"));
      out.house = console.house();
    } catch (const console::ConsoleError& e) {
      ADD_FAILURE() << "console: " << e.what();
    }
  }
  runner.stop();
}

HouseRun mapThreeRooms(const std::string& dir) {
  HouseRun out;
  const std::string mapPath = dir + "/three.map";
  std::ofstream(mapPath) << threeRoomMap();
  const sim::WorldLoad world = sim::World::load(mapPath);
  EXPECT_TRUE(world.world) << world.error;
  ElfLoad load = ElfImage::load(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf");
  EXPECT_TRUE(load.image) << load.error;
  const std::unique_ptr<TcpLink> tcp = listenOnFreePort(51000);
  EXPECT_TRUE(tcp) << "no free port";
  if (!world.world || !load.image || !tcp) return out;

  std::atomic<bool> consoleDone{false};
  EmulatedRunOptions o;
  o.brick.startCol = 5;
  o.brick.startRow = 6;
  o.brick.heading = sim::Heading::N;
  o.brick.link = tcp.get();
  o.pressEnterAtS = -1;  // never: the PC's house commands start everything
  o.stopWhenExplored = false;
  o.maxSeconds = 3600;  // emulated; the console's wait ends the run long before
  o.onEvent = [&](uint64_t) { return consoleDone.load(); };
  EmulatedRun emulated(*load.image, *world.world, o);
  const auto start = std::chrono::steady_clock::now();
  std::thread brick([&] { out.brick = emulated.run(); });
  driveConsole(tcp->port(), out);
  consoleDone = true;
  brick.join();
  out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

int countLinesStartingWith(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0 ? 1 : 0;
  return n;
}

TEST(HouseEndToEnd, ConsoleMapsThreeRoomsThroughTheFirmwareWithoutAButton) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a whole house at emulation speed: make test runs this from the Release build";
#endif
  if (!std::filesystem::exists(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf"))
    GTEST_SKIP() << "no nxtmap-sim.elf";
  char dirTemplate[] = "/tmp/nxtmap-house-e2e-XXXXXX";
  ASSERT_NE(::mkdtemp(dirTemplate), nullptr);
  const HouseRun r = mapThreeRooms(dirTemplate);
  std::filesystem::remove_all(dirTemplate);
  std::printf("house end to end: %.1f s wall, %.1f s emulated, %s", r.wallSeconds, r.brick.emulatedSeconds,
              r.waitAnswer.c_str());

  EXPECT_FALSE(r.brick.fault) << r.brick.fault.describe();
  ASSERT_TRUE(r.connected) << "the console never connected";
  EXPECT_NE(r.waitAnswer.find("house mapped"), std::string::npos) << r.waitAnswer;
  EXPECT_EQ(countLinesStartingWith(r.roomsText, "room "), 3) << r.roomsText;
  ASSERT_EQ(r.house.rooms().size(), 3u) << r.roomsText;
  for (size_t i = 0; i < r.house.rooms().size(); ++i) {
    // Every room mapped: at least 90 % of the smallest room's free cells known free.
    EXPECT_GE(r.house.rooms()[i].map.count(CellState::Free), kSmallestRoomCells * 9 / 10) << "room " << i;
  }
  // Each doorway passed once: two gateways, a chain (one room joined to both others).
  ASSERT_EQ(r.house.gateways().size(), 2u) << r.roomsText;
  std::set<std::pair<int, int>> pairs;
  int shared = -1;
  for (const network::Gateway& g : r.house.gateways()) {
    EXPECT_NE(g.roomA, g.roomB);
    pairs.insert({std::min(g.roomA, g.roomB), std::max(g.roomA, g.roomB)});
  }
  EXPECT_EQ(pairs.size(), 2u) << "two different doorways";
  for (int room = 0; room < 3; ++room)
    if (r.house.gatewaysBetween(room, (room + 1) % 3).size() + r.house.gatewaysBetween(room, (room + 2) % 3).size() ==
        2)
      shared = room;
  EXPECT_GE(shared, 0) << "the middle room joins both others";
}

#endif

}  // namespace
}  // namespace nxtmap::emu::test
