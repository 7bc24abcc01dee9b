// The link end to end: the stand-in brick (the core explorer + the brick's protocol code) and
// the PC session over a byte pipe at the NXT's 460800 baud, clean and with 5 % damaged bytes
// and a forced disconnect. The PC's map must equal the brick's grid cell for cell, and no
// command may run twice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "host/link/LinkHarness.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/WheelModel.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::link {
namespace {

sim::World roomWorld() {
  return sim::World::fromRows({
      "##################",
      "#................#",
      "#................#",
      "#....##..........#",
      "#....##.....#....#",
      "#...........#....#",
      "#................#",
      "#..#.............#",
      "#................#",
      "##################",
  });
}

SimBrickConfig brickConfig() {
  SimBrickConfig c;
  c.run.startCol = 2;
  c.run.startRow = 5;
  c.actionMs = 10;
  c.cellMs = 20;
  return c;
}

// Every cell of the brick's grid window equals the PC's copy, and the copy holds nothing else.
::testing::AssertionResult sameMap(const RoomGrid& grid, const MirrorMap& copy) {
  const Bounds w = grid.window();
  size_t known = 0;
  for (int y = w.minY; y <= w.maxY; ++y) {
    for (int x = w.minX; x <= w.maxX; ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      if (grid.at(c) != copy.at(c)) {
        return ::testing::AssertionFailure()
               << "cell (" << x << "," << y << "): brick " << int(grid.at(c)) << ", PC " << int(copy.at(c));
      }
      if (grid.at(c) != CellState::Unknown) ++known;
    }
  }
  if (known != copy.known()) return ::testing::AssertionFailure() << copy.known() - known << " extra cells on the PC";
  return ::testing::AssertionSuccess() << known << " known cells equal";
}

bool noRepeats(const std::vector<uint16_t>& seqs) {
  return std::set<uint16_t>(seqs.begin(), seqs.end()).size() == seqs.size();
}

TEST(LinkEndToEnd, CleanLinkMapsTheRoomAndReachesAGoal) {
  const sim::World world = roomWorld();
  SimBrick brick(world, brickConfig());
  Session pc;
  LinkHarness h(brick, pc, HarnessConfig{});
  ASSERT_TRUE(h.runUntil([&] { return pc.connected(); }, 1000));
  pc.explore();
  ASSERT_TRUE(h.runUntil([&] { return brick.mode() == protocol::BrickMode::Done; }, 600000));
  std::printf("clean run: explored in %u ms, %u cells moved\n", h.nowMs(), brick.counters().cellsMoved);
  ASSERT_TRUE(
      h.runUntil([&] { return brick.link().mapSync().inFlight() == 0 && !brick.link().mapSync().pending(); }, 5000));
  EXPECT_TRUE(sameMap(brick.grid(), pc.map()));
  EXPECT_GT(pc.map().known(), 100u);

  // A goal: back to the start cell along the cells the PC knows are free (a straight path here).
  const Pose at = brick.pose();
  std::vector<Cell> path{at.cell};
  Cell c = at.cell;
  while (c != Cell{0, 0}) {
    c = Cell{static_cast<int16_t>(c.x + (c.x < 0   ? 1
                                         : c.x > 0 ? -1
                                                   : 0)),
             static_cast<int16_t>(c.y + (c.y < 0   ? 1
                                         : c.y > 0 ? -1
                                                   : 0))};
    path.push_back(c);
  }
  const uint16_t seq = pc.followPath(path, 1);
  const bool ended = h.runUntil(
      [&] {
        return pc.pathProgress() && pc.pathProgress()->pathId == 1 &&
               pc.pathProgress()->state != protocol::PathState::Following;
      },
      20000);
  ASSERT_TRUE(ended);
  EXPECT_TRUE(pc.acknowledged(seq));
  // Either reached, or blocked at a cell the world really blocks (the straight line may cross an obstacle).
  if (pc.pathProgress()->state == protocol::PathState::Reached) {
    EXPECT_EQ(brick.pose().cell, (Cell{0, 0}));
    ASSERT_TRUE(pc.pose().has_value());
    EXPECT_TRUE(h.runUntil([&] { return pc.pose()->cell == Cell{0, 0}; }, 1000));
  } else {
    EXPECT_EQ(pc.pathProgress()->state, protocol::PathState::Blocked);
  }
  EXPECT_TRUE(noRepeats(brick.executed()));
  EXPECT_EQ(brick.executed().size(), 2u);
}

// What the brick learns of its wheels reaches the PC (Counters): an uncalibrated robot's turn error and
// drift, as the brick's pilot learnt them (the turns' error learnt the right way round in this small room).
TEST(LinkEndToEnd, ThePcHearsWhatTheBrickLearntOfItsWheels) {
  // An uncalibrated robot in a small room: what the brick learnt of its turns reaches the PC to the 10 ppm. One
  // room's walls teach the turns' error with its sign in most runs, not all (measured, seeds 1-12: 9 of 12, RMS
  // error 1.6 % against the true 2 %; a robot that learnt nothing keeps the store's 0 in all 12).
  const sim::World world = roomWorld();
  int learnt = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    SimBrickConfig c = brickConfig();
    c.run.noise = *sim::noiseProfileByName("nxt-uncalibrated");
    c.run.seed = seed;
    SimBrick brick(world, c);
    Session pc;
    LinkHarness h(brick, pc, HarnessConfig{});
    ASSERT_TRUE(h.runUntil([&] { return pc.connected(); }, 1000)) << seed;
    pc.explore();
    ASSERT_TRUE(h.runUntil([&] { return brick.mode() == protocol::BrickMode::Done; }, 600000)) << seed;
    const uint32_t done = h.nowMs();
    ASSERT_TRUE(h.runUntil([&] { return h.nowMs() > done + 3000; }, 5000));  // a Counters after the last drive
    ASSERT_TRUE(pc.brickCounters().has_value()) << seed;
    EXPECT_EQ(pc.brickCounters()->wheelTurn10Ppm,
              (brick.wheels().turnPpm + (brick.wheels().turnPpm >= 0 ? 5 : -5)) / 10)
        << seed;
    EXPECT_EQ(pc.brickCounters()->wheelDrift10UradPerM,
              (brick.wheels().driftUradPerM + (brick.wheels().driftUradPerM >= 0 ? 5 : -5)) / 10)
        << seed;
    const sim::WheelModel truth(c.run.noise.wheels, 5.6, 11.2, c.run.seed);
    const double turnPct = pc.brickCounters()->wheelTurn10Ppm * 1e-3;
    if (turnPct * truth.systematicTurnError() > 0.0 && std::abs(turnPct) > 0.5) ++learnt;  // its sign, not the 0
  }
  EXPECT_GE(learnt, 8);
}

TEST(LinkEndToEnd, FivePercentDamagedBytesAndADisconnectLoseNothingAndRunNothingTwice) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const sim::World world = roomWorld();
    SimBrick brick(world, brickConfig());
    Session pc(SessionConfig{static_cast<uint32_t>(0x5EED0000u + seed), 250, 250});  // deterministic bytes
    HarnessConfig hc;
    hc.toPc = LossConfig::fivePercent(seed * 100 + 1);
    hc.toBrick = LossConfig::fivePercent(seed * 100 + 2);
    LinkHarness h(brick, pc, hc);
    // Hello (22 bytes) and its reply (27) each get through about a third of the time.
    ASSERT_TRUE(h.runUntil([&] { return pc.connected(); }, 30000)) << seed;
    const uint16_t exploreSeq = pc.explore();
    // A stop and a resume in the middle, sent while bytes are being damaged.
    ASSERT_TRUE(h.runUntil([&] { return brick.counters().cellsMoved >= 10; }, 120000))
        << seed << " mode " << int(brick.mode()) << " executed " << brick.executed().size() << " moved "
        << brick.counters().cellsMoved << " finished " << brick.finished();
    pc.stop();
    pc.explore();
    // Disconnect in the middle of the run, for two seconds.
    ASSERT_TRUE(h.runUntil([&] { return brick.counters().cellsMoved >= 25; }, 120000)) << seed;
    h.disconnect(2000);
    ASSERT_TRUE(h.runUntil([&] { return brick.mode() == protocol::BrickMode::Done; }, 900000)) << seed;
    ASSERT_TRUE(h.runUntil(
        [&] {
          return pc.commandsDone() && brick.link().mapSync().inFlight() == 0 && !brick.link().mapSync().pending();
        },
        200000))
        << "seed " << seed << " connected " << pc.connected() << " commands done " << pc.commandsDone() << " in flight "
        << brick.link().mapSync().inFlight() << " pending " << brick.link().mapSync().pending() << " brick connected "
        << brick.link().connected() << " pc error '" << pc.error() << "'";
    std::printf("seed %d converged at %u ms; limit %zu, retransmits %u\n", int(seed), h.nowMs(),
                brick.link().mapSync().payloadLimit(), brick.link().counters().retransmits);
    // Let a few acknowledgements and statuses cross the damaged link.
    h.runUntil([] { return false; }, 1000);
    EXPECT_TRUE(sameMap(brick.grid(), pc.map())) << "seed " << seed;
    EXPECT_TRUE(noRepeats(brick.executed())) << seed;
    EXPECT_EQ(brick.executed().size(), 3u) << seed;
    EXPECT_EQ(brick.executed().front(), exploreSeq);
    // The faults really happened.
    EXPECT_GT(h.toPc().counters().dropped, 10u);
    EXPECT_GT(h.toPc().counters().corrupted, 10u);
    EXPECT_GT(h.toPc().counters().duplicated, 10u);
    EXPECT_GT(h.toBrick().counters().dropped + h.toBrick().counters().corrupted, 0u);
    EXPECT_GE(pc.counters().connects, 2u);
    EXPECT_GT(brick.link().counters().retransmits, 0u);
  }
}

}  // namespace
}  // namespace nxtmap::link
