// The console's house on the stand-in brick (sim: link, SimBrick), shared by the console's house tests
// (ConsoleHouseTest, ConsoleHouseRouteTest): a two-room world (cells), its house of two rooms and a
// gateway (frames a quarter turn apart), and a console connected to the brick with that house loaded.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "host/console/Console.hpp"
#include "host/link/SimTransport.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/network/HouseFiles.hpp"
#include "tests/support/TempDir.hpp"

namespace nxtmap::console::test {

using network::RoomMap;
using ::nxtmap::test::TempDir;

// Two rooms joined by a one-cell doorway at world (7, 3). The robot starts at (3, 3) facing up.
inline const char* kWorldRows[] = {
    "################", "#......#.......#", "#......#.......#", "#..............#",
    "#......#.......#", "#......#.......#", "################",
};
inline constexpr int kStartCol = 3, kStartRow = 3;

inline std::string worldFile(const test::TempDir& tmp) {
  std::string text = "type octile\nheight 7\nwidth 16\nmap\n";
  for (const char* r : kWorldRows) text += std::string(r) + "\n";
  for (char& c : text)
    if (c == '#') c = '@';
  return tmp.write("two-rooms.map", text);
}

inline bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

inline bool worldBlocked(int col, int row) {
  return col < 0 || row < 0 || row >= 7 || col >= 16 || kWorldRows[row][col] == '#';
}

// The room's map from the world's truth over a box of its frame.
inline RoomMap truthMap(const mapping::FrameTransform& f, int minX, int minY, int w, int h) {
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
inline network::HouseNetwork twoRoomHouse(bool withIsland = false) {
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

inline network::HouseLoad savedHouse(const test::TempDir& tmp, const std::string& name, bool withIsland = false) {
  std::string error;
  EXPECT_TRUE(network::saveHouse(twoRoomHouse(withIsland), 0.10, tmp.path(name), error)) << error;
  network::HouseLoad load = network::loadHouse(tmp.path(name));
  EXPECT_TRUE(load.network.has_value()) << load.error;
  return load;
}

}  // namespace nxtmap::console::test
