// Acceptance of the radio link, end to end through the emulated brick: the real firmware image
// (nxtmap-sim.elf) explores a published room while the PC's Session pulls the map over the emulated
// Bluetooth stream, then the PC sends a path to a goal and the robot drives it. Once over a clean link
// and once with 5 % of the bytes dropped, corrupted or duplicated both ways plus one forced
// disconnect: the PC's map must equal the brick's grid cell for cell, the goal must be reached and
// no command may run twice.
#include "EmuTestSupport.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/link/LossyPipe.hpp"
#include "host/link/Session.hpp"
#include "host/mapping/FrameTransform.hpp"
#include "host/sim/World.hpp"

#include <filesystem>
#include <map>
#include <queue>

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR

// A shortest 4-neighbour path over the PC's known-free cells (cell 0 = from), empty if none.
std::vector<Cell> pathOnMirror(const link::MirrorMap& map, Cell from, Cell to) {
  std::map<std::pair<int, int>, Cell> parent;
  std::queue<Cell> open;
  open.push(from);
  parent[{from.x, from.y}] = from;
  while (!open.empty()) {
    const Cell c = open.front();
    open.pop();
    if (c == to) break;
    for (const Dir d : {Dir::North, Dir::East, Dir::South, Dir::West}) {
      const Cell n = advance(c, d);
      if (map.at(n) != CellState::Free || parent.count({n.x, n.y})) continue;
      parent[{n.x, n.y}] = c;
      open.push(n);
    }
  }
  if (!parent.count({to.x, to.y})) return {};
  std::vector<Cell> path{to};
  while (!(path.back() == from)) path.push_back(parent[{path.back().x, path.back().y}]);
  return {path.rbegin(), path.rend()};
}

struct Outcome {
  bool explored = false, reached = false;
  int differ = -1;  // cells where the PC's map and the brick's grid disagree
  uint32_t commandsRun = 0, duplicates = 0;
  uint64_t damaged = 0;
  double seconds = 0;
};

Outcome runLink(bool lossy) {
  Outcome out;
  const std::string elf = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf";
  ElfLoad load = ElfImage::load(elf);
  EXPECT_TRUE(load.image) << load.error;
  if (!load.image) return out;
  const sim::WorldLoad world =
      sim::World::load(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/occupancy-120.map");
  EXPECT_TRUE(world.world) << world.error;
  if (!world.world) return out;

  MemoryLink radio;
  EmulatedRunOptions o;
  o.brick.startCol = 1;
  o.brick.startRow = 20;
  o.brick.heading = sim::Heading::N;
  o.brick.link = &radio;
  o.pressEnterAtS = -1;  // the PC starts the exploration
  o.stopWhenExplored = false;
  o.maxSeconds = 900;

  link::Session pc;
  link::LossyPipe up(lossy ? link::LossConfig::fivePercent(11) : link::LossConfig{});
  link::LossyPipe down(lossy ? link::LossConfig::fivePercent(12) : link::LossConfig{});
  const mapping::FrameTransform frame(1, 20, sim::Heading::N);
  const Cell goal = frame.toExplorer(18, 3);
  enum class Phase { Explore, Goal, Settle } phase = Phase::Explore;
  uint32_t lastMs = 0, disconnectAt = 0, settleUntil = 0;
  bool disconnected = false, forced = false, exploreSent = false;
  uint16_t pathSeq = 0;

  o.onEvent = [&](uint64_t cycles) {
    const auto ms = static_cast<uint32_t>(cycles / (kMckHz / 1000));
    if (ms == lastMs) return false;
    lastMs = ms;
    // One forced disconnect in the lossy run, 20 s into the exploration, for 3 s.
    if (lossy && !forced && ms >= 20000) {
      forced = disconnected = true;
      disconnectAt = ms;
      radio.pcConnected = false;
      radio.toBrick.clear();
      pc.linkLost();
    }
    if (disconnected && ms >= disconnectAt + 3000) {
      disconnected = false;
      radio.pcConnected = true;
    }
    if (!disconnected) {
      if (!radio.fromBrick.empty()) {
        const std::vector<uint8_t> bytes = down.pass(radio.fromBrick);
        pc.receive(bytes.data(), bytes.size(), ms);
      }
      const std::vector<uint8_t> sent = pc.transmit(ms);
      if (!sent.empty()) {
        const std::vector<uint8_t> bytes = up.pass(sent);
        radio.toBrick.insert(radio.toBrick.end(), bytes.begin(), bytes.end());
      }
    }
    radio.fromBrick.clear();  // bytes sent while the link is down are lost
    if (!pc.connected()) return false;
    if (!exploreSent) {
      pc.explore();  // queued until acknowledged, through the disconnect; the brick runs it once
      exploreSent = true;
    }
    if (phase == Phase::Explore && pc.status() && pc.status()->mode == protocol::BrickMode::Done) {
      out.explored = true;
      const std::vector<Cell> path = pathOnMirror(pc.map(), pc.status()->pose.cell, goal);
      if (path.size() < 2) return true;  // no path on the PC's map: the test fails below
      pathSeq = pc.followPath(path, 7);
      phase = Phase::Goal;
    }
    if (phase == Phase::Goal && pc.pathProgress() && pc.pathProgress()->pathId == 7 &&
        pc.pathProgress()->state == protocol::PathState::Reached) {
      out.reached = true;
      phase = Phase::Settle;
      settleUntil = ms + 5000;  // let the last map deltas and counters arrive
    }
    // Counters are unreliable and periodic (every other second): on the lossy link several in a row
    // may be lost, so wait (up to 60 s) for ones sent after the path ran, rather than judge stale ones.
    const bool countersAfterPath = pc.brickCounters() && pc.brickCounters()->link.commandsRun >= 2;
    return phase == Phase::Settle && ms >= settleUntil && pc.commandsDone() &&
           (countersAfterPath || ms >= settleUntil + 55000);
  };
  EmulatedRun emulated(*load.image, *world.world, o);
  const EmulatedRunReport r = emulated.run();
  EXPECT_FALSE(r.fault) << r.fault.describe();
  out.seconds = r.emulatedSeconds;
  const auto brickMap = emulated.exportedMap();
  EXPECT_TRUE(brickMap.has_value()) << "g_mapExport has no MAP1 magic";
  if (brickMap) {
    out.differ = 0;
    for (int y = brickMap->minY; y < brickMap->minY + brickMap->height; ++y)
      for (int x = brickMap->minX; x < brickMap->minX + brickMap->width; ++x)
        if (static_cast<CellState>(brickMap->at(x, y)) !=
            pc.map().at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}))
          ++out.differ;
  }
  if (pc.brickCounters()) {
    out.commandsRun = pc.brickCounters()->link.commandsRun;
    out.duplicates = pc.brickCounters()->link.duplicates;
  }
  out.damaged = up.counters().dropped + up.counters().corrupted + up.counters().duplicated + down.counters().dropped +
                down.counters().corrupted + down.counters().duplicated;
  (void)pathSeq;
  return out;
}

class EmulatedLinkEndToEnd : public ::testing::TestWithParam<bool> {};

TEST_P(EmulatedLinkEndToEnd, PcMapEqualsTheBrickGoalReachedNoCommandTwice) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "a whole room at emulation speed: make test runs this from the Release build";
#endif
  if (!std::filesystem::exists(std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap-sim.elf"))
    GTEST_SKIP() << "no nxtmap-sim.elf";
  const bool lossy = GetParam();
  const Outcome o = runLink(lossy);
  EXPECT_TRUE(o.explored) << "after " << o.seconds << " s";
  EXPECT_TRUE(o.reached) << "after " << o.seconds << " s";
  EXPECT_EQ(o.differ, 0) << "cells where the PC's map and the brick's grid disagree";
  EXPECT_EQ(o.commandsRun, 2u) << "explore and one path, each run exactly once";
  if (lossy) {
    EXPECT_GT(o.damaged, 100u) << "the lossy link damaged too few bytes to prove anything";
  }
}

INSTANTIATE_TEST_SUITE_P(CleanAndLossy, EmulatedLinkEndToEnd, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "Lossy" : "Clean"; });

#endif

}  // namespace
}  // namespace nxtmap::emu::test
