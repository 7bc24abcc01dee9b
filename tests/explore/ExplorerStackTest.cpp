// ExplorerStack from outside: runs of each strategy against a scripted robot in a small walled room
// (cells of 10 cm, the published set-up), the run's life cycle (start drops a run, end keeps the
// map) and what it reports without a run. Memory: a host ExplorerBuffer of the brick's capacity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "common/explore/ExplorerStack.hpp"
#include "host/mapping/ExplorerBuffer.hpp"

namespace nxtmap {
namespace {

// A room of free cells x in [0, width), y in [0, height) in the explorer's frame (the robot starts
// on (0,0) facing +y), walled all round.
struct Room {
  int width = 5, height = 6;
  bool inside(Cell c) const { return c.x >= 0 && c.x < width && c.y >= 0 && c.y < height; }
  bool wall(Cell c) const {
    const bool onRing = c.x >= -1 && c.x <= width && c.y >= -1 && c.y <= height && !inside(c);
    const bool corner = (c.x == -1 || c.x == width) && (c.y == -1 || c.y == height);
    return onRing && !corner;  // the corners cannot be seen along an axis: left out of the checks
  }
  bool blocked(Cell c) const { return !inside(c); }
};

// Cell step of a heading in eighths of a turn (0 = +y, clockwise).
Cell stepOf(int eighths) {
  static const int kDx[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  static const int kDy[8] = {1, 1, 0, -1, -1, -1, 0, 1};
  const int e = ((eighths % 8) + 8) % 8;
  return Cell{static_cast<int16_t>(kDx[e]), static_cast<int16_t>(kDy[e])};
}

// The robot of the script: its cell and heading follow every action exactly; a reading is the
// distance from its cell centre to the near face of the first blocked cell along the sensor.
struct ScriptedRobot {
  const Room& room;
  RangeGeometry geometry;
  Cell cell{};      // the start: (0,0)
  int heading = 0;  // eighths, clockwise from +y
  int aheadShortCm = 0;  // the front sensor reads this much short (the robot stands nearer the wall ahead)

  DriveEvent answer(const DriveAction& a) {
    switch (a.kind) {
      case DriveAction::Kind::Read: return DriveEvent::range(a.sensor, read(a.sensor));
      case DriveAction::Kind::Rotate:
        heading += static_cast<int>(std::lround(a.value / 785.398));
        return DriveEvent::rotated();
      case DriveAction::Kind::Drive: return DriveEvent::driven(!drive(a.value));
      case DriveAction::Kind::Think:
      case DriveAction::Kind::Done: break;
    }
    return DriveEvent::thought();
  }
  RangeReading read(Sensor s) const {
    const Cell d = stepOf(heading + 2 * static_cast<int>(s));
    RangeReading r;
    r.samples = 1;
    int k = 1;
    while (k <= 40 && !room.blocked(offset(cell, d.x * k, d.y * k))) ++k;
    const int cm = (2 * k - 1) * geometry.cellCm / 2 - geometry.mountCm;
    r.status =
        cm <= geometry.minCm ? RangeStatus::TooNear : (cm > geometry.maxCm ? RangeStatus::TooFar : RangeStatus::Good);
    r.cm = static_cast<int16_t>(r.status == RangeStatus::Good ? cm - (s == Sensor::Front ? aheadShortCm : 0) : 0);
    return r;
  }
  // False when the way is blocked (the robot stays).
  bool drive(int32_t mm) {
    const bool diagonal = heading % 2 != 0;
    const int cells = static_cast<int>(std::lround(mm / (geometry.cellCm * 10.0 * (diagonal ? std::sqrt(2.0) : 1.0))));
    const Cell d = stepOf(cells >= 0 ? heading : heading + 4);
    Cell c = cell;
    for (int i = 0; i < std::abs(cells); ++i) {
      c = offset(c, d.x, d.y);
      if (room.blocked(c)) return false;
    }
    cell = c;
    return true;
  }
};

// Draws the room into the map: its cells free, its walls blocked.
void drawRoom(MapLayers& map, const Room& room) {
  for (int y = -1; y <= room.height; ++y) {
    for (int x = -1; x <= room.width; ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      if (room.inside(c)) {
        ASSERT_TRUE(map.markVisited(c));
      }
      if (room.wall(c)) {
        ASSERT_TRUE(map.markBlocked(c));
      }
    }
  }
}

// Carries out actions until the run is over or `limit` actions were carried out; returns them.
int runToEnd(ExplorerStack& stack, DriveAction a, ScriptedRobot& robot, int limit = 20000) {
  int n = 0;
  while (!stack.finished() && n < limit) {
    a = stack.step(robot.answer(a));
    ++n;
  }
  return n;
}

struct StackRig {
  mapping::ExplorerBuffer buffer;
  ExplorerStack stack{buffer.memory(), ExplorerConfig{}};
};

bool zero(const Counters& c) {
  return c.sensorRequests == 0 && c.rawSamples == 0 && c.cellsMoved == 0 && c.turnEighths == 0 && c.blockedMoves == 0 &&
         c.correctionMrad == 0;
}

struct Case {
  const char* name;
  Strategy strategy;
  bool drawnFirst;  // the room is in the map before the run starts
};

TEST(ExplorerStack, ARunOfEachMappingStrategyInASmallRoomEndsDoneWithTheRoomMapped) {
  const Case cases[] = {
      {"propagation, room unknown", Strategy::Propagation, false},
      {"frontier, room unknown", Strategy::Frontier, false},
      {"propagation, room drawn into the map", Strategy::Propagation, true},
      {"frontier, room drawn into the map", Strategy::Frontier, true},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const Room room{5, 6};
    StackRig rig;
    if (c.drawnFirst) drawRoom(rig.stack.map(), room);
    ScriptedRobot robot{room, rig.stack.config().geometry};
    const int actions = runToEnd(rig.stack, rig.stack.start(c.strategy, PilotConfig{}), robot);
    ASSERT_TRUE(rig.stack.finished()) << actions << " actions";
    EXPECT_EQ(rig.stack.step(DriveEvent::thought()).kind, DriveAction::Kind::Done);
    EXPECT_EQ(rig.stack.explorer()->end(), ExplorerEnd::Complete);
    EXPECT_EQ(rig.stack.strategy(), c.strategy);
    EXPECT_EQ(rig.stack.propagation() != nullptr, c.strategy == Strategy::Propagation);
    for (int y = -1; y <= room.height; ++y) {
      for (int x = -1; x <= room.width; ++x) {
        const Cell cell{static_cast<int16_t>(x), static_cast<int16_t>(y)};
        if (room.inside(cell)) {
          EXPECT_EQ(rig.stack.map().at(cell), CellState::Free) << x << "," << y;
        }
        if (room.wall(cell)) {
          EXPECT_EQ(rig.stack.map().at(cell), CellState::Occupied) << x << "," << y;
        }
      }
    }
  }
}

TEST(ExplorerStack, GoToReachesItsTargetOverAKnownMapAndReportsFinished) {
  struct Trip {
    Cell target;
  };
  const Room room{5, 6};
  for (const Trip& t : {Trip{Cell{4, 5}}, Trip{Cell{0, 5}}, Trip{Cell{4, 0}}, Trip{Cell{2, 3}}}) {
    SCOPED_TRACE(std::to_string(t.target.x) + "," + std::to_string(t.target.y));
    StackRig rig;
    drawRoom(rig.stack.map(), room);
    ScriptedRobot robot{room, rig.stack.config().geometry};
    const int actions = runToEnd(rig.stack, rig.stack.start(Strategy::GoTo, PilotConfig{}, Pose{}, t.target), robot);
    ASSERT_TRUE(rig.stack.finished()) << actions << " actions";
    ASSERT_NE(rig.stack.goTo(), nullptr);
    EXPECT_TRUE(rig.stack.goTo()->arrived());
    EXPECT_EQ(rig.stack.explorer()->pose().cell, t.target);
    EXPECT_EQ(robot.cell, t.target);  // the robot is where the stack believes it is
    EXPECT_EQ(rig.stack.counters().blockedMoves, 0u);
    EXPECT_GE(rig.stack.counters().cellsMoved, static_cast<uint32_t>(std::max(t.target.x, t.target.y)));
  }
}

TEST(ExplorerStack, StartDropsThePreviousRunAndKeepsTheMap) {
  const Room room{5, 6};
  StackRig rig;
  ScriptedRobot robot{room, rig.stack.config().geometry};
  DriveAction a = rig.stack.start(Strategy::Frontier, PilotConfig{});
  for (int i = 0; i < 40; ++i) a = rig.stack.step(robot.answer(a));
  const int32_t freeBefore = rig.stack.map().grid().count(CellState::Free);
  ASSERT_GT(rig.stack.counters().sensorRequests, 0u);
  ASSERT_GT(freeBefore, 0);

  const Pose here = rig.stack.explorer()->pose();
  const DriveAction first = rig.stack.start(Strategy::Propagation, PilotConfig{}, here);
  EXPECT_EQ(rig.stack.strategy(), Strategy::Propagation);
  EXPECT_NE(rig.stack.propagation(), nullptr);
  EXPECT_FALSE(rig.stack.finished());
  EXPECT_LE(rig.stack.counters().sensorRequests, 1u);  // the new run's own first read at most
  EXPECT_EQ(rig.stack.counters().cellsMoved, 0u);
  EXPECT_EQ(rig.stack.explorer()->pose().cell, here.cell);
  EXPECT_GE(rig.stack.map().grid().count(CellState::Free), freeBefore);
  EXPECT_EQ(robot.cell, here.cell);
  runToEnd(rig.stack, first, robot);
  EXPECT_TRUE(rig.stack.finished());
  EXPECT_EQ(rig.stack.explorer()->end(), ExplorerEnd::Complete);
}

TEST(ExplorerStack, EndDropsTheRunAndLeavesTheMap) {
  const Room room{5, 6};
  StackRig rig;
  ScriptedRobot robot{room, rig.stack.config().geometry};
  runToEnd(rig.stack, rig.stack.start(Strategy::Frontier, PilotConfig{}), robot);
  ASSERT_TRUE(rig.stack.finished());
  const int32_t free = rig.stack.map().grid().count(CellState::Free);
  const int32_t occupied = rig.stack.map().grid().count(CellState::Occupied);
  rig.stack.end();
  EXPECT_FALSE(rig.stack.running());
  EXPECT_FALSE(rig.stack.finished());
  EXPECT_EQ(rig.stack.explorer(), nullptr);
  EXPECT_EQ(rig.stack.pilot(), nullptr);
  EXPECT_TRUE(zero(rig.stack.counters()));
  EXPECT_EQ(rig.stack.step(DriveEvent::thought()).kind, DriveAction::Kind::Done);
  EXPECT_EQ(rig.stack.map().grid().count(CellState::Free), free);
  EXPECT_EQ(rig.stack.map().grid().count(CellState::Occupied), occupied);
  EXPECT_EQ(rig.stack.map().at(Cell{2, 3}), CellState::Free);
}

TEST(ExplorerStack, TheBelievedOffsetIsTheRunningPilotsOnceItsExplorerHasStarted) {
  const Room room{5, 6};
  StackRig rig;
  int32_t x = 7, y = 7;
  EXPECT_FALSE(rig.stack.believedOffset(x, y));  // no run
  EXPECT_EQ(x, 0);
  EXPECT_EQ(y, 0);
  ScriptedRobot robot{room, rig.stack.config().geometry};
  robot.aheadShortCm = 2;
  DriveAction a = rig.stack.start(Strategy::Propagation, PilotConfig{});
  bool moved = false;
  for (int n = 0; n < 400 && !rig.stack.finished(); ++n) {
    // The wall ahead reads 2 cm near: the pilot takes the robot for 2 cm past its cell's centre.
    const DriveEvent e = robot.answer(a);
    a = rig.stack.step(e);
    ASSERT_TRUE(rig.stack.believedOffset(x, y));
    EXPECT_EQ(x, rig.stack.pilot()->tracker().xMm());
    EXPECT_EQ(y, rig.stack.pilot()->tracker().yMm());
    moved = moved || x != 0 || y != 0;
  }
  EXPECT_TRUE(moved);
  rig.stack.end();
  EXPECT_FALSE(rig.stack.believedOffset(x, y));
  EXPECT_EQ(x, 0);
  EXPECT_EQ(y, 0);
}

TEST(ExplorerStack, WithoutARunNothingRunsAndTheCountersAreZero) {
  for (const int cells : {16, 64, 128}) {
    SCOPED_TRACE(cells);
    mapping::ExplorerBuffer buffer(*mapping::GridCapacity::ofCells(cells));
    ExplorerStack stack(buffer.memory(), ExplorerConfig{});
    EXPECT_FALSE(stack.running());
    EXPECT_FALSE(stack.finished());
    EXPECT_EQ(stack.explorer(), nullptr);
    EXPECT_EQ(stack.pilot(), nullptr);
    EXPECT_EQ(stack.propagation(), nullptr);
    EXPECT_EQ(stack.goTo(), nullptr);
    EXPECT_TRUE(zero(stack.counters()));
    EXPECT_EQ(stack.map().grid().capacityWidth(), cells);
    EXPECT_EQ(stack.map().grid().count(CellState::Free), 0);
  }
}

}  // namespace
}  // namespace nxtmap
