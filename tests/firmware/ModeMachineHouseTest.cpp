// The house commands in the brick's mode machine, from outside: a confined Explore, GoTo, EnterRoom
// and Scan from the PC in; the mode, room ids, the new room's frame, the goal's progress, the room's
// exits and the readings (what BrickLink reports) out, with the robot of ModeMachineRig driving (an open floor).
#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tests/firmware/ModeMachineRig.hpp"

namespace nxtmap::fw::test {
namespace {
using Mode = protocol::BrickMode;
using protocol::PathState;

constexpr uint32_t kDriveLimitMs = 240000;  // far more than any command here takes with the rig's wheels

protocol::Command confinedExplore() {
  protocol::Command c = commandOf(protocol::CommandKind::Explore);
  c.explore.confine = true;
  return c;
}

protocol::Command goTo(uint16_t goalId, Cell target) {
  protocol::Command c = commandOf(protocol::CommandKind::GoTo);
  c.goTo.goalId = goalId;
  c.goTo.target = target;
  return c;
}

protocol::Command setPose(const Pose& p) {
  protocol::Command c = commandOf(protocol::CommandKind::SetPose);
  c.pose = p;
  return c;
}

// The PC's upload of an open floor: every cell of `window` free.
protocol::Command openFloor(const Bounds& window) {
  protocol::Command c = commandOf(protocol::CommandKind::MapChunk);
  c.chunk.chunkIndex = 0;
  c.chunk.chunkCount = 1;
  c.chunk.window = window;
  c.chunk.count = static_cast<uint16_t>(window.width() * window.height());
  for (uint16_t i = 0; i < c.chunk.count; ++i) c.chunk.setState(i, CellState::Free);
  return c;
}

void press(Brick& b, Button button) {
  b.modes.readButton(button, b.now);
  b.modes.readButton(button, b.now + ModeMachine::kButtonStableMs);
  b.modes.readButton(Button::None, b.now + ModeMachine::kButtonStableMs + 1);
  b.modes.readButton(Button::None, b.now + 2 * ModeMachine::kButtonStableMs + 1);
}

TEST(ModeMachineHouse, AConfinedExploreStartsTheNextRoomOnAClearedMap) {
  for (uint16_t roomsBefore : {0, 1, 3}) {
    Brick b;
    for (uint16_t i = 0; i < roomsBefore; ++i) press(b, Button::Left);
    (void)b.stack.map().markBlocked(Cell{2, 2});
    const uint16_t epoch = b.link.mapEpoch();
    b.modes.carryOut(confinedExplore(), b.now);
    const protocol::BrickReport r = b.modes.report(7400);
    EXPECT_EQ(b.modes.mode(), Mode::Exploring) << roomsBefore;
    EXPECT_EQ(r.mode, Mode::Exploring) << roomsBefore;
    EXPECT_EQ(b.modes.roomId(), roomsBefore + 1);
    EXPECT_EQ(r.roomId, roomsBefore + 1);
    EXPECT_EQ(r.fromRoom, roomsBefore);
    ASSERT_NE(r.exits, nullptr) << "a house room reports its exits";
    EXPECT_EQ(r.exits->roomId, roomsBefore + 1);
    EXPECT_EQ(r.exits->end, ExplorerEnd::Running);
    EXPECT_NE(b.link.mapEpoch(), epoch) << "the map restarts for the PC";
    EXPECT_EQ(b.modes.grid().at(Cell{2, 2}), CellState::Unknown) << "the new room's map starts empty";
    EXPECT_TRUE(b.runner.busy()) << "the room's first action runs";
  }
}

TEST(ModeMachineHouse, GoToReportsFollowingThenHowItEndedWithTheGoalId) {
  struct Case {
    std::string name;
    Cell target;
    bool stalled;
    PathState first;  // right after the command (None: not checked, the brick may level itself first)
    PathState last;
    std::optional<Cell> endCell;  // where the robot believes it stands at the end (nullopt: not checked)
  };
  const Case cases[] = {
      {"already there", Cell{0, 0}, false, PathState::Reached, PathState::Reached, Cell{0, 0}},
      {"ahead", Cell{0, 3}, false, PathState::Following, PathState::Reached, Cell{0, 3}},
      {"aside", Cell{2, 1}, false, PathState::Following, PathState::Reached, Cell{2, 1}},
      {"wheels held", Cell{0, 3}, true, PathState::Following, PathState::Blocked, std::nullopt},
      {"outside the map", Cell{9, 9}, false, PathState::None, PathState::Blocked, Cell{0, 0}},
  };
  for (const Case& c : cases) {
    Brick b;
    b.stalled = c.stalled;
    b.modes.carryOut(openFloor(Bounds{-3, -3, 3, 4}), b.now);
    b.modes.carryOut(setPose(Pose{Cell{0, 0}, Dir::North}), b.now);
    b.modes.carryOut(goTo(42, c.target), b.now);
    EXPECT_EQ(b.modes.report(7400).path.pathId, 42) << c.name;
    if (c.first != PathState::None) {
      EXPECT_EQ(b.modes.report(7400).path.state, c.first) << c.name;
    }
    if (c.first == PathState::Following) {
      EXPECT_EQ(b.modes.mode(), Mode::Following) << c.name;
    }
    ASSERT_TRUE(b.runUntil([&] { return !b.modes.moving(); }, kDriveLimitMs)) << c.name;
    const protocol::BrickReport r = b.modes.report(7400);
    EXPECT_EQ(r.path.pathId, 42) << c.name;
    EXPECT_EQ(r.path.state, c.last) << c.name;
    if (c.endCell) {
      EXPECT_EQ(r.pose.cell, *c.endCell) << c.name;
    }
    EXPECT_NE(r.pose.cell == c.target, c.last == PathState::Blocked) << c.name << ": at the goal iff reached";
    EXPECT_EQ(r.mode, Mode::Idle) << c.name;
    EXPECT_FALSE(b.modes.wheelsDriven()) << c.name;
  }
}

TEST(ModeMachineHouse, EnterRoomCrossesAndReportsTheNewRoomWithItsFrame) {
  struct Case {
    std::string name;
    Dir heading, outward;
    uint8_t depth;
    Cell origin;  // the new room's (0, 0) in the old room's frame: depth + 1 cells outward from inside
  };
  const Case cases[] = {
      {"straight on", Dir::North, Dir::North, 1, Cell{0, 2}},
      {"turn right first", Dir::North, Dir::East, 2, Cell{3, 0}},
      {"turn about first", Dir::East, Dir::West, 1, Cell{-2, 0}},
  };
  for (const Case& c : cases) {
    Brick b;
    press(b, Button::Left);
    b.modes.carryOut(confinedExplore(), b.now);  // the house's room 2
    b.modes.carryOut(setPose(Pose{Cell{0, 0}, c.heading}), b.now);
    protocol::Command enter = commandOf(protocol::CommandKind::EnterRoom);
    enter.enterRoom.roomId = 7;
    enter.enterRoom.inside = Cell{0, 0};
    enter.enterRoom.outward = c.outward;
    enter.enterRoom.door.alongX = c.outward == Dir::North || c.outward == Dir::South;
    enter.enterRoom.door.first = advance(Cell{0, 0}, c.outward);
    enter.enterRoom.door.width = 4;
    enter.enterRoom.door.depth = c.depth;
    const uint16_t epoch = b.link.mapEpoch();
    b.modes.carryOut(enter, b.now);
    EXPECT_EQ(b.modes.mode(), Mode::Exploring) << c.name << ": crossing";
    EXPECT_EQ(b.modes.roomId(), 2) << c.name << ": still in the old room";
    ASSERT_TRUE(b.runUntil([&] { return b.modes.roomId() != 2; }, kDriveLimitMs)) << c.name;
    const protocol::BrickReport r = b.modes.report(7400);
    EXPECT_EQ(r.roomId, 7) << c.name;
    EXPECT_EQ(r.fromRoom, 2) << c.name;
    EXPECT_EQ(r.roomOrigin, c.origin) << c.name;
    EXPECT_EQ(r.roomHeading, c.outward) << c.name;
    EXPECT_EQ(r.pose.cell, (Cell{0, 0})) << c.name << ": the robot stands at the new room's origin";
    EXPECT_EQ(r.mode, Mode::Exploring) << c.name << ": mapping the new room";
    ASSERT_NE(r.exits, nullptr) << c.name;
    EXPECT_EQ(r.exits->roomId, 7) << c.name;
    EXPECT_NE(b.link.mapEpoch(), epoch) << c.name << ": the map restarts for the PC";
  }
}

// A standing scan: the four sensors read where the robot stands, Front, Right, Back, Left, reported
// with the PC's scan id and the pose; the robot does not move.
TEST(ModeMachineHouse, ScanReadsTheFourSensorsStandingAndReportsThemWithItsId) {
  struct Case {
    std::string name;
    Pose at;
    uint8_t rawCm[kSensorCount];  // what the sensor on Front, Right, Back, Left reads
    RangeStatus status[kSensorCount];
    int16_t cm[kSensorCount];  // what it reports: the LEGO sensor's linear error (0.9757 x + 1.88 cm) taken off
  };
  const Case cases[] = {
      {"walls all round",
       Pose{Cell{1, 2}, Dir::East},
       {40, 61, 22, 90},
       {RangeStatus::Good, RangeStatus::Good, RangeStatus::Good, RangeStatus::Good},
       {39, 61, 21, 90}},
      {"open behind, too near ahead",
       Pose{Cell{-2, 0}, Dir::South},
       {3, 50, Brick::kNoEchoCm, 150},
       {RangeStatus::TooNear, RangeStatus::Good, RangeStatus::NoEcho, RangeStatus::TooFar},
       {0, 49, 0, 0}},
  };
  for (const Case& c : cases) {
    Brick b;
    // The house's room 1: a closet (every sensor reads a face 14 cm off), mapped at once. (With no echo all
    // round the floor is open without end: the robot would turn to trust its blind zone and map on.)
    for (I2cSlaveModel& s : b.sensors) s.regs[0x42] = 14;
    b.modes.carryOut(confinedExplore(), b.now);
    ASSERT_TRUE(b.runUntil([&] { return !b.house.running(); }, kDriveLimitMs)) << c.name;
    for (int i = 0; i < kSensorCount; ++i) b.sensors[b.config.sensorPorts[i]].regs[0x42] = c.rawCm[i];
    b.modes.carryOut(setPose(c.at), b.now);
    protocol::Command scan = commandOf(protocol::CommandKind::Scan);
    scan.scan.scanId = 9;
    b.modes.carryOut(scan, b.now);
    EXPECT_EQ(b.modes.mode(), Mode::Exploring) << c.name << ": reading";
    ASSERT_NE(b.modes.report(7400).readings, nullptr) << c.name;
    EXPECT_EQ(b.modes.report(7400).readings->scanId, 0) << c.name << ": not before it is done";
    ASSERT_TRUE(b.runUntil([&] { return !b.modes.moving(); }, kDriveLimitMs)) << c.name;
    const protocol::BrickReport r = b.modes.report(7400);
    EXPECT_EQ(r.mode, Mode::Idle) << c.name;
    EXPECT_EQ(r.pose.cell, c.at.cell) << c.name << ": it did not move";
    EXPECT_EQ(r.pose.heading, c.at.heading) << c.name;
    ASSERT_NE(r.readings, nullptr) << c.name;
    EXPECT_EQ(r.readings->scanId, 9) << c.name;
    EXPECT_EQ(r.readings->scanPose.cell, c.at.cell) << c.name;
    EXPECT_EQ(r.readings->scanPose.heading, c.at.heading) << c.name;
    for (int i = 0; i < kSensorCount; ++i) {
      EXPECT_EQ(r.readings->scan[i].status, c.status[i]) << c.name << ", sensor " << i;
      if (c.status[i] == RangeStatus::Good) {
        EXPECT_EQ(r.readings->scan[i].cm, c.cm[i]) << c.name << ", sensor " << i;
      }
      EXPECT_GT(r.readings->scan[i].samples, 0) << c.name << ", sensor " << i;
    }
    EXPECT_FALSE(b.modes.wheelsDriven()) << c.name;
  }
}

TEST(ModeMachineHouse, AnyOtherCommandButtonOrFaultAbortsTheHouseWhereItStands) {
  struct Case {
    std::string name;
    std::function<void(Brick&)> interrupt;
    Mode mode;
    uint16_t room;
  };
  const Case cases[] = {
      {"Stop", [](Brick& b) { b.modes.carryOut(commandOf(protocol::CommandKind::Stop), b.now); }, Mode::Idle, 0},
      {"Exit button", [](Brick& b) { press(b, Button::Exit); }, Mode::Idle, 0},
      {"a fault", [](Brick& b) { b.modes.halt(); }, Mode::Fault, 0},
      {"Left button: a new room", [](Brick& b) { press(b, Button::Left); }, Mode::Idle, 1},
      {"plain Explore", [](Brick& b) { b.modes.carryOut(commandOf(protocol::CommandKind::Explore), b.now); },
       Mode::Exploring, 0},
  };
  for (const Case& c : cases) {
    Brick b;
    b.modes.carryOut(openFloor(Bounds{-3, -3, 3, 6}), b.now);
    b.modes.carryOut(setPose(Pose{Cell{0, 0}, Dir::North}), b.now);
    b.modes.carryOut(goTo(5, Cell{0, 5}), b.now);
    ASSERT_TRUE(b.runUntil([&] { return b.modes.pose().cell.y >= 2; }, kDriveLimitMs)) << c.name;
    const Pose there = b.house.pose();
    c.interrupt(b);
    const protocol::BrickReport r = b.modes.report(7400);
    EXPECT_FALSE(b.modes.houseActive()) << c.name;
    EXPECT_FALSE(b.house.running()) << c.name;
    EXPECT_EQ(r.mode, c.mode) << c.name;
    EXPECT_EQ(r.roomId, c.room) << c.name;
    EXPECT_EQ(r.exits, nullptr) << c.name << ": no house reports after it";
    if (c.room == 0) {
      EXPECT_EQ(r.pose.cell, there.cell) << c.name << ": the robot rests where the house left it";
    }
    if (c.mode != Mode::Exploring) {
      EXPECT_FALSE(b.modes.wheelsDriven()) << c.name;
    }
  }
}

// The house's runs start from what the brick keeps of its wheels (stored in flash, or learnt by the runs before
// the house) and keep what they learnt when a command is over, as an explorer run does.
TEST(ModeMachineHouse, AHouseCommandStartsFromTheWheelsKeptAndKeepsWhatItsRunsLearnt) {
  WheelCalibration stored;
  stored.driftUradPerM = 21700;
  stored.turnPpm = -9400;
  stored.driftVariance = 9000000;
  stored.turnVariance = 360000;
  struct Case {
    std::string name;
    std::optional<WheelCalibration> kept;  // in flash when switched on (nullopt: nothing)
    int writes;                            // flash writes by the end of the GoTo
  };
  const Case cases[] = {
      {"wheels kept", stored, 0},  // an open floor teaches nothing: nothing to write
      {"nothing kept", std::nullopt, 1},
  };
  for (const Case& c : cases) {
    Brick b = c.kept ? Brick(*c.kept) : Brick();
    b.modes.carryOut(openFloor(Bounds{-3, -3, 3, 4}), b.now);
    b.modes.carryOut(setPose(Pose{Cell{0, 0}, Dir::North}), b.now);
    b.modes.carryOut(goTo(7, Cell{0, 3}), b.now);
    ASSERT_NE(b.stack.pilot(), nullptr) << c.name;
    EXPECT_TRUE(WheelRecord::same(b.stack.pilot()->wheels(), c.kept.value_or(WheelCalibration{}))) << c.name;
    ASSERT_TRUE(b.runUntil([&] { return !b.modes.moving(); }, kDriveLimitMs)) << c.name;
    EXPECT_EQ(b.modes.report(7400).path.state, PathState::Reached) << c.name;
    EXPECT_EQ(b.wheels.writes, c.writes) << c.name;
    ASSERT_TRUE(b.wheels.kept.has_value()) << c.name;
    EXPECT_TRUE(WheelRecord::same(*b.wheels.kept, b.stack.pilot()->wheels())) << c.name;
  }
}

}  // namespace
}  // namespace nxtmap::fw::test
