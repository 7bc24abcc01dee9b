// The brick's mode machine from outside: buttons (debounced) and PC commands in, the mode, room,
// pose, map and motor command out. The parts it drives are the real ones (explorer stack on a
// 16 x 16 grid, action runner, brick link: ModeMachineRig); the wheels do not turn here.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/firmware/ModeMachineRig.hpp"

namespace nxtmap::fw::test {
namespace {
using Mode = protocol::BrickMode;

struct Press {
  Button button;
  uint32_t atMs;
};

TEST(ModeMachine, ButtonsCountOnceHeldFor50MsAndChangeTheMode) {
  struct Case {
    std::string name;
    std::vector<Press> presses;
    Mode mode;
    uint16_t room;
    bool run;  // a run exists (a stopped one resumes on the next Explore)
  };
  const Press enter[] = {{Button::Enter, 0}, {Button::Enter, 50}};
  const Case cases[] = {
      {"nothing", {}, Mode::Idle, 0, false},
      {"enter too short", {{Button::Enter, 0}, {Button::Enter, 49}}, Mode::Idle, 0, false},
      {"enter held", {enter[0], enter[1]}, Mode::Exploring, 0, true},
      {"right held", {{Button::Right, 0}, {Button::Right, 60}}, Mode::Exploring, 0, true},
      {"enter then exit", {enter[0], enter[1], {Button::Exit, 60}, {Button::Exit, 110}}, Mode::Idle, 0, true},
      {"exit then left drops the run",
       {enter[0], enter[1], {Button::Exit, 60}, {Button::Exit, 110}, {Button::Left, 120}, {Button::Left, 170}},
       Mode::Idle,
       1,
       false},
      {"left: new room", {{Button::Left, 0}, {Button::Left, 50}}, Mode::Idle, 1, false},
      {"left held long counts once",
       {{Button::Left, 0}, {Button::Left, 50}, {Button::Left, 500}},
       Mode::Idle,
       1,
       false},
      {"left twice",
       {{Button::Left, 0},
        {Button::Left, 50},
        {Button::None, 60},
        {Button::None, 110},
        {Button::Left, 120},
        {Button::Left, 170}},
       Mode::Idle,
       2,
       false},
      {"a bounce restarts the wait",
       {enter[0], {Button::None, 30}, {Button::Enter, 40}, {Button::Enter, 80}},
       Mode::Idle,
       0,
       false},
  };
  for (const Case& c : cases) {
    Brick b;
    for (const Press& p : c.presses) b.modes.readButton(p.button, p.atMs);
    EXPECT_EQ(b.modes.mode(), c.mode) << c.name;
    EXPECT_EQ(b.modes.roomId(), c.room) << c.name;
    EXPECT_EQ(b.modes.hasRun(), c.run) << c.name;
  }
}

TEST(ModeMachine, PcCommandsExploreStopAndSetThePose) {
  Brick b;
  const uint32_t v0 = b.modes.mapVersion();
  b.modes.carryOut(commandOf(protocol::CommandKind::Explore), 0);
  EXPECT_EQ(b.modes.mode(), Mode::Exploring);
  EXPECT_EQ(b.stack.strategy(), Strategy::Frontier);
  EXPECT_NE(b.modes.mapVersion(), v0);
  b.modes.carryOut(commandOf(protocol::CommandKind::Stop), 1);
  EXPECT_EQ(b.modes.mode(), Mode::Idle);
  EXPECT_TRUE(b.modes.hasRun());  // a stopped run resumes on the next Explore
  protocol::Command set = commandOf(protocol::CommandKind::SetPose);
  set.pose = Pose{Cell{3, -2}, Dir::East};
  b.modes.carryOut(set, 2);
  EXPECT_FALSE(b.modes.hasRun());
  EXPECT_EQ(b.modes.pose().cell, (Cell{3, -2}));
  EXPECT_EQ(b.modes.report(7400).pose.cell, (Cell{3, -2}));
  EXPECT_EQ(b.modes.report(7400).batteryMillivolts, 7400);
  b.modes.carryOut(commandOf(protocol::CommandKind::Explore), 3);
  EXPECT_EQ(b.modes.pose().cell, (Cell{3, -2})) << "a new run starts where the robot stands";
}

TEST(ModeMachine, MapChunkReplacesTheMap) {
  Brick b;
  (void)b.stack.map().markBlocked(Cell{5, 5});
  protocol::MapChunkMsg chunk;
  chunk.chunkIndex = 0;
  chunk.chunkCount = 1;
  chunk.window = Bounds{0, 0, 2, 0};  // cells (0,0) (1,0) (2,0)
  chunk.count = 3;
  chunk.setState(0, CellState::Free);
  chunk.setState(1, CellState::Occupied);
  chunk.setState(2, CellState::Unknown);
  protocol::Command c = commandOf(protocol::CommandKind::MapChunk);
  c.chunk = chunk;
  b.modes.carryOut(c, 0);
  const RoomGrid& g = b.modes.grid();
  EXPECT_EQ(g.at(Cell{0, 0}), CellState::Free);
  EXPECT_EQ(g.at(Cell{1, 0}), CellState::Occupied);
  EXPECT_EQ(g.at(Cell{2, 0}), CellState::Unknown);
  EXPECT_EQ(g.at(Cell{5, 5}), CellState::Unknown) << "chunk 0 clears the old map";
}

TEST(ModeMachine, MotorsBrakedUnlessMovingAndHaltFaults) {
  Brick b;
  b.modes.driveMotors();
  EXPECT_EQ(b.motors.brakeMask, ModeMachine::kAllBrakes);
  EXPECT_EQ(b.motors.pwm[0], 0);
  b.modes.carryOut(commandOf(protocol::CommandKind::Explore), 0);
  b.modes.halt();
  EXPECT_EQ(b.modes.mode(), Mode::Fault);
  EXPECT_FALSE(b.modes.wheelsDriven());
  b.motors.brakeMask = 0;
  b.safety.trip(MotorSafety::Reason::Encoder);
  b.modes.driveMotors();
  EXPECT_EQ(b.motors.brakeMask, 0) << "a tripped safety leaves the command to the tick";
}

}  // namespace
}  // namespace nxtmap::fw::test

namespace nxtmap::fw::test {
namespace {

// A run on an empty map first sweeps square to the walls (the pilot has not started its explorer yet);
// a run on a map the PC sent keeps the map's frame and starts mapping at once.
TEST(ModeMachine, ARunOnAnEmptyMapSquaresToTheWallsFirst) {
  const struct {
    const char* what;
    bool mapSent;
    bool sweeps;
  } table[] = {{"empty map", false, true}, {"the PC's map", true, false}};
  for (const auto& row : table) {
    Brick b;
    if (row.mapSent) {
      protocol::MapChunkMsg chunk;
      chunk.chunkIndex = 0;
      chunk.chunkCount = 1;
      chunk.window = Bounds{0, 0, 0, 0};
      chunk.count = 1;
      chunk.setState(0, CellState::Free);
      protocol::Command c = commandOf(protocol::CommandKind::MapChunk);
      c.chunk = chunk;
      b.modes.carryOut(c, 0);
    }
    b.modes.carryOut(commandOf(protocol::CommandKind::Explore), 1);
    ASSERT_NE(b.stack.pilot(), nullptr) << row.what;
    EXPECT_EQ(!b.stack.pilot()->explorerStarted(), row.sweeps) << row.what;
    EXPECT_EQ(b.stack.pilot()->squaring().result().found, false) << row.what;  // nothing read yet
    EXPECT_EQ(b.modes.pose().cell, (Cell{0, 0})) << row.what << ": where it stands while it sweeps";
  }
}

// The PC's Calibrate (reported as exploring meanwhile) on an open floor with no echo at all: nothing to measure
// by, and it never drives off to look for a wall; it rests where it stood, what it holds of the wheels kept.
// (Its sweeps and whole turns: FlashKeep's and the console's end-to-end tests, with walls.)
TEST(ModeMachine, ACalibrationWithNoWallInReachRestsWhereItStood) {
  Brick b;
  protocol::Command set = commandOf(protocol::CommandKind::SetPose);
  set.pose = Pose{Cell{2, -1}, Dir::East};
  b.modes.carryOut(set, 0);
  const uint8_t finishes = b.modes.finishes();
  b.modes.carryOut(commandOf(protocol::CommandKind::Calibrate), 1);
  EXPECT_EQ(b.modes.mode(), Mode::Exploring);
  ASSERT_NE(b.stack.pilot(), nullptr);
  EXPECT_FALSE(b.stack.pilot()->explorerStarted()) << "it sweeps first";
  int32_t drivenMs = 0;
  const bool rested = b.runUntil(
      [&] {
        const int8_t l = b.motors.pwm[0], r = b.motors.pwm[1];
        drivenMs += (l > 0 && r > 0) || (l < 0 && r < 0) ? 1 : 0;  // both wheels one way: a drive
        return b.modes.mode() != Mode::Exploring;
      },
      600000);
  ASSERT_TRUE(rested) << "still calibrating after 10 minutes";
  EXPECT_EQ(b.modes.mode(), Mode::Idle);
  EXPECT_EQ(b.modes.finishes(), static_cast<uint8_t>(finishes + 1));
  EXPECT_EQ(b.modes.pose().cell, (Cell{2, -1})) << "rests where it stood";
  EXPECT_EQ(b.modes.pose().heading, Dir::East);
  EXPECT_EQ(drivenMs, 0) << "never drove";
  EXPECT_FALSE(b.modes.hasRun());
  EXPECT_EQ(b.wheels.writes, 1) << "what it holds of the wheels is kept";
  EXPECT_EQ(b.modes.motorsDriven(), false);
}

// What the runs learnt of the wheels outlives switching the brick off: the kept wheels are reported at once and
// are where the next run's learning starts; an explorer run stopped keeps what its pilot holds then; a save of
// what is kept already writes nothing.
TEST(ModeMachine, TheWheelsKeptAreWhereTheNextRunStartsAndAStoppedRunKeepsItsOwn) {
  WheelCalibration stored;
  stored.driftUradPerM = -33500;  // (the tracker keeps 100 urad/m steps, 10 ppm, as it hands them out)
  stored.turnPpm = 17800;
  stored.driftVariance = 4000000;
  stored.turnVariance = 250000;
  Brick b(stored);
  EXPECT_EQ(b.modes.report(7400).wheelDriftUradPerM, -33500) << "told the PC before any run";
  EXPECT_EQ(b.modes.report(7400).wheelTurnPpm, 17800);
  b.modes.carryOut(commandOf(protocol::CommandKind::Explore), 0);
  ASSERT_NE(b.stack.pilot(), nullptr);
  EXPECT_TRUE(WheelRecord::same(b.stack.pilot()->wheels(), stored)) << "the run starts from what was kept";
  b.modes.carryOut(commandOf(protocol::CommandKind::Stop), 1);
  ASSERT_TRUE(b.wheels.kept.has_value());
  EXPECT_TRUE(WheelRecord::same(*b.wheels.kept, b.stack.pilot()->wheels()));
  EXPECT_EQ(b.wheels.writes, 0) << "nothing learnt on an open floor: nothing written";

  Brick fresh;  // nothing kept: an uncalibrated robot's first outing
  EXPECT_EQ(fresh.modes.report(7400).wheelDriftUradPerM, 0);
  fresh.modes.carryOut(commandOf(protocol::CommandKind::Explore), 0);
  EXPECT_EQ(fresh.wheels.writes, 0) << "a run that goes on keeps nothing yet";
  fresh.modes.carryOut(commandOf(protocol::CommandKind::Stop), 1);
  EXPECT_EQ(fresh.wheels.writes, 1);
  ASSERT_TRUE(fresh.wheels.kept.has_value());
  EXPECT_TRUE(WheelRecord::same(*fresh.wheels.kept, fresh.stack.pilot()->wheels()));
  fresh.modes.carryOut(commandOf(protocol::CommandKind::Stop), 2);
  EXPECT_EQ(fresh.wheels.writes, 1) << "a stop while resting is no run's end";
}

}  // namespace
}  // namespace nxtmap::fw::test
