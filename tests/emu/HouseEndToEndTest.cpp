// Mapping a HouseExpo house end to end through the emulated brick: the real firmware (nxtmap-sim.elf,
// the published robot's 10 cm cells, the brick's 64 x 64 grid) runs in the emulated brick behind a
// loopback TCP link, and the PC console (its LinkRunner and Console, as `nxtmap connect` builds them)
// types `explore house`, then `wait house SECONDS` and `rooms`. No button is ever pressed: the brick
// maps each room confined (house commands Explore{confine}, GoTo, EnterRoom) and the console's house
// planner joins them. The house (HouseExpoHouse: house_expo_room_0000, three reachable plan rooms) must
// be mapped as a house (HouseExpoHouse::expectAHouse), beside sim-house on the same seed, noise and grid.
#include "EmuTestSupport.hpp"
#include "HouseExpoHouse.hpp"
#include "host/console/Console.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/link/LinkRunner.hpp"
#include "host/link/LinkSpec.hpp"
#include "host/link/Transport.hpp"
#include "host/network/HouseFiles.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <thread>

#include <unistd.h>

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR

constexpr double kWaitHouseS = 1200.0;  // wall seconds the console waits (about 150 s on an idle PC)

struct HouseRun {
  bool connected = false;
  std::string waitAnswer, roomsText;
  network::HouseNetwork house;
  uint16_t brickRoom = 0;  // the brick's room counter at the end
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
      out.brickRoom = runner.with([](link::Session& s) { return s.status() ? s.status()->roomId : uint16_t{0}; });
    } catch (const console::ConsoleError& e) {
      ADD_FAILURE() << "console: " << e.what();
    }
  }
  runner.stop();
}

HouseRun mapHouse(const HouseExpoHouse& h) {
  HouseRun out;
  ElfLoad load = ElfImage::load(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf");
  EXPECT_TRUE(load.image) << load.error;
  const std::unique_ptr<TcpLink> tcp = listenOnFreePort(51000);
  EXPECT_TRUE(tcp) << "no free port";
  if (!load.image || !tcp) return out;

  std::atomic<bool> consoleDone{false};
  EmulatedRunOptions o;
  o.brick.startPose = *h.site.start;
  o.brick.noise = *sim::noiseProfileByName("typical");
  o.brick.seed = HouseExpoHouse::seed();
  o.brick.link = tcp.get();
  o.pressEnterAtS = -1;  // never: the PC's house commands start everything
  o.stopWhenExplored = false;
  o.maxSeconds = 4 * 3600;  // emulated; the console's wait ends the run long before
  o.onEvent = [&](uint64_t) { return consoleDone.load(); };
  EmulatedRun emulated(*load.image, h.site, o);
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

// A failed run is not reproducible (the brick draws its noise on the link's timing), so the house it mapped
// is saved (as `nxtmap sim-house --save` writes one) with the console's answers, and the place printed.
void keepForInspection(const HouseRun& r, const sim::World& world) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                    ("nxtmap-house-e2e-seed" + std::to_string(HouseExpoHouse::seed()) + "-" +
                                     std::to_string(::getpid()));
  std::string error;
  if (!network::saveHouse(r.house, world.resolutionM(), dir.string(), error)) {
    std::printf("the mapped house was not kept: %s\n", error.c_str());
    return;
  }
  std::FILE* f = std::fopen((dir / "console.txt").c_str(), "w");
  if (f) {
    std::fprintf(f, "%s\n%s", r.waitAnswer.c_str(), r.roomsText.c_str());
    std::fclose(f);
  }
  std::printf("the mapped house and the console's answers are kept in %s\n", dir.c_str());
}

TEST(HouseEndToEnd, ConsoleMapsAHouseExpoHouseThroughTheFirmwareWithoutAButton) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a whole house at emulation speed: make test runs this from the Release build";
#endif
  if (!std::filesystem::exists(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf"))
    GTEST_SKIP() << "no nxtmap-sim.elf";
  const std::optional<HouseExpoHouse> h = HouseExpoHouse::load();
  ASSERT_TRUE(h);
  const HouseRun r = mapHouse(*h);
  std::printf("house end to end: %.1f s wall, %.1f s emulated, %s", r.wallSeconds, r.brick.emulatedSeconds,
              r.waitAnswer.c_str());

  EXPECT_FALSE(r.brick.fault) << r.brick.fault.describe();
  ASSERT_TRUE(r.connected) << "the console never connected";
  ASSERT_NE(r.waitAnswer.find("house mapped"), std::string::npos) << r.waitAnswer;
  const int rooms = static_cast<int>(r.house.rooms().size());
  EXPECT_EQ(countLinesStartingWith(r.roomsText, "room "), rooms) << r.roomsText;
  EXPECT_EQ(r.brickRoom, rooms) << "no room started twice (the brick's room counter)";
  h->expectAHouse(r.house, "console over TCP");
  if (::testing::Test::HasFailure()) keepForInspection(r, h->truth);
}

#endif

}  // namespace
}  // namespace nxtmap::emu::test
