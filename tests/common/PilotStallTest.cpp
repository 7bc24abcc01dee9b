// The pilot when the body meets something on a rotation (the wheels stall and the encoders count only what
// was turned, as the brick's drive layer reports it): a quarter turn stalled part way is finished by a three-point
// turn, or turned back and heard by the explorer as its way blocked; a stalled levelling is not tried again until the robot has moved; a stalled
// step of the start's sweep ends the sweep. And on a drive: a steered drive that stalls is driven again
// square to its line before the explorer hears that its way is blocked.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/motion/Pilot.hpp"
#include "tests/common/PilotRoomRig.hpp"

namespace nxtmap {
namespace {

using pilotrig::Rig;

bool isQuarter(const DriveAction& a) { return a.kind == DriveAction::Kind::Rotate && std::abs(a.value) > 700; }

// Open space's answer to `a`: nothing in range, exact rotations, each drive `shortMm` short of what was asked.
DriveEvent openSpace(const DriveAction& a, int32_t shortMm = 0) {
  if (a.kind == DriveAction::Kind::Read) {
    RangeReading far;
    far.status = RangeStatus::TooFar;
    far.samples = 1;
    return DriveEvent::range(a.sensor, far);
  }
  if (a.kind == DriveAction::Kind::Rotate) return DriveEvent::rotatedBy(a.value);
  if (a.kind == DriveAction::Kind::Drive)
    return DriveEvent::drivenBy(a.value > 0 ? a.value - shortMm : a.value + shortMm);
  return DriveEvent::thought();
}

// Open space (nothing in range), exact wheels, until the pilot asks for a quarter turn or `limit` steps.
DriveAction untilQuarterTurn(Rig& rig, DriveAction a, int limit = 2000) {
  for (int i = 0; i < limit && !rig.pilot.finished() && !isQuarter(a); ++i) a = rig.pilot.step(openSpace(a));
  return a;
}

TEST(PilotStall, AStalledQuarterTurnIsTurnedBackAndTheExplorersWayIsBlocked) {
  // Stalled at once, after a twentieth and after nine tenths of the turn (too little or too much of it for a
  // three-point turn, ThreePointTurn): each is turned back by what it turned.
  for (const int twentieths : {0, 1, 18}) {
    Rig rig;
    const DriveAction turn = untilQuarterTurn(rig, rig.pilot.step(DriveEvent::start()));
    ASSERT_TRUE(isQuarter(turn)) << twentieths;
    const Pose before = rig.explorer.pose();
    const Dir wanted = rotate(before.heading, turn.value > 0 ? 1 : -1);
    const int8_t evidence = rig.map.evidence(advance(before.cell, wanted));
    const int32_t got = turn.value * twentieths / 20;
    const DriveAction back = rig.pilot.step(DriveEvent::rotatedBy(got));
    ASSERT_EQ(back.kind, DriveAction::Kind::Rotate) << twentieths;
    EXPECT_EQ(back.value, -got) << twentieths;
    rig.pilot.step(DriveEvent::rotatedBy(-got));
    EXPECT_EQ(rig.explorer.counters().blockedMoves, 1u) << twentieths;
    EXPECT_EQ(rig.explorer.pose().heading, before.heading) << twentieths;  // it never faced the new way
    // The map is not changed (the cell it was to move to may well be free); the cell it stands in is one
    // where no turn is planned again.
    EXPECT_EQ(rig.map.evidence(advance(before.cell, wanted)), evidence) << twentieths;
    EXPECT_EQ(rig.pilot.tracker().thetaMrad(), 0) << twentieths;
  }
}

TEST(PilotStall, TurnsThatAlwaysStallAreGivenUp) {
  // Every quarter turn stalls at once: the robot can only drive along its first heading. No turn is tried
  // again where one stalled (8 cells), then each stall makes the cell it turned towards more suspect, until
  // the explorer has nowhere left to turn to and ends.
  Rig rig;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  int stalls = 0;
  for (int i = 0; i < 20000 && !rig.pilot.finished(); ++i) {
    a = untilQuarterTurn(rig, a, 20000);
    if (rig.pilot.finished()) break;
    ++stalls;
    a = rig.pilot.step(DriveEvent::rotatedBy(0));
    ASSERT_EQ(a.kind, DriveAction::Kind::Rotate);
    a = rig.pilot.step(DriveEvent::rotatedBy(0));
  }
  EXPECT_TRUE(rig.pilot.finished());
  EXPECT_GE(stalls, 2);
  EXPECT_EQ(rig.explorer.counters().blockedMoves, static_cast<uint32_t>(stalls));
}

TEST(PilotStall, AfterAStalledTurnTheNextQuarterTurnIsAWholeQuarter) {
  Rig rig;
  const DriveAction turn = untilQuarterTurn(rig, rig.pilot.step(DriveEvent::start()));
  ASSERT_TRUE(isQuarter(turn));
  const Cell stalledAt = rig.explorer.pose().cell;
  rig.pilot.step(DriveEvent::rotatedBy(turn.value / 20));  // too little for a three-point turn: given up
  const DriveAction next = untilQuarterTurn(rig, rig.pilot.step(DriveEvent::rotatedBy(-turn.value / 20)));
  ASSERT_TRUE(isQuarter(next));
  EXPECT_NEAR(std::abs(next.value), 1571, 1);      // the stalled quarter is not owed any more
  EXPECT_NE(rig.explorer.pose().cell, stalledAt);  // and it is not tried where it stalled
}

// Open space until a quarter turn, which stalls at `stalledMrad`: the pilot's answer (a three-point turn's drive out).
struct StalledTurn {
  Pose before;
  DriveAction turn, out;
};
StalledTurn stallTheFirstQuarterTurn(Rig& rig, int32_t stalledMrad) {
  StalledTurn s;
  s.turn = untilQuarterTurn(rig, rig.pilot.step(DriveEvent::start()));
  s.before = rig.explorer.pose();
  s.out = rig.pilot.step(DriveEvent::rotatedBy(s.turn.value > 0 ? stalledMrad : -stalledMrad));
  return s;
}

TEST(PilotStall, AQuarterTurnStalledPartWayIsFinishedByAThreePointTurn) {
  // Stalled at 500 mrad: out 25 mm along the partial heading (forward: neither side is known free and not the
  // other), the rest of the turn, and the explorer faces its new way with the tracker knowing where the drive put
  // the robot: 25 cos 0.5 = 22 mm along the old heading, 25 sin 0.5 = 12 mm towards the new one.
  Rig rig;
  const StalledTurn s = stallTheFirstQuarterTurn(rig, 500);
  ASSERT_TRUE(isQuarter(s.turn));
  ASSERT_EQ(s.out.kind, DriveAction::Kind::Drive);
  EXPECT_EQ(s.out.value, ThreePointTurn::outMm(500));
  const DriveAction rest = rig.pilot.step(DriveEvent::drivenBy(s.out.value));
  ASSERT_EQ(rest.kind, DriveAction::Kind::Rotate);
  const int32_t sign = s.turn.value > 0 ? 1 : -1;
  EXPECT_EQ(rest.value, s.turn.value - sign * 500);
  rig.pilot.step(DriveEvent::rotatedBy(rest.value));
  const Dir wanted = rotate(s.before.heading, sign);
  EXPECT_EQ(rig.explorer.pose().heading, wanted);
  EXPECT_EQ(rig.explorer.pose().cell, s.before.cell);
  EXPECT_EQ(rig.explorer.counters().blockedMoves, 0u);
  EXPECT_NEAR(rig.pilot.tracker().along(s.before.heading), 22, 1);
  EXPECT_NEAR(rig.pilot.tracker().along(wanted), 12, 1);
}

TEST(PilotStall, AThreePointTurnWhoseRestStallsIsGivenUpBackWhereItStarted) {
  Rig rig;
  const StalledTurn s = stallTheFirstQuarterTurn(rig, 500);
  ASSERT_EQ(s.out.kind, DriveAction::Kind::Drive);
  const int32_t sign = s.turn.value > 0 ? 1 : -1;
  rig.pilot.step(DriveEvent::drivenBy(s.out.value));
  const DriveAction back = rig.pilot.step(DriveEvent::rotatedBy(sign * 200));  // stalls again
  ASSERT_EQ(back.kind, DriveAction::Kind::Rotate);
  EXPECT_EQ(back.value, -sign * 200);
  const DriveAction in = rig.pilot.step(DriveEvent::rotatedBy(back.value));
  ASSERT_EQ(in.kind, DriveAction::Kind::Drive);
  EXPECT_EQ(in.value, -s.out.value);
  const DriveAction turnBack = rig.pilot.step(DriveEvent::drivenBy(in.value));
  ASSERT_EQ(turnBack.kind, DriveAction::Kind::Rotate);
  EXPECT_EQ(turnBack.value, -sign * 500);
  rig.pilot.step(DriveEvent::rotatedBy(turnBack.value));
  EXPECT_EQ(rig.explorer.counters().blockedMoves, 1u);  // the explorer hears its way blocked, as for any stall
  EXPECT_EQ(rig.explorer.pose().heading, s.before.heading);
  EXPECT_NEAR(rig.pilot.tracker().along(s.before.heading), 0, 1);  // out and back in
  EXPECT_NEAR(rig.pilot.tracker().along(rotate(s.before.heading, 1)), 0, 1);
  EXPECT_EQ(rig.pilot.tracker().thetaMrad(), 0);
}

TEST(PilotStall, AStalledLevellingIsNotTriedAgainUntilTheRobotHasMoved) {
  // Every quarter turn ends 40 mrad past its target and every small rotation (levelling, steering) stalls
  // at once: the heading error stays. Between two drives the pilot levels at most once.
  Rig rig;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  int levels = 0, levelsSinceDrive = 0, unlevelledReads = 0, drives = 0;
  bool lastWasSmallRotation = false;
  for (int i = 0; i < 3000 && !rig.pilot.finished(); ++i) {
    DriveEvent e = DriveEvent::thought();
    if (a.kind == DriveAction::Kind::Read) {
      if (lastWasSmallRotation) {
        ++levels;
        EXPECT_LE(++levelsSinceDrive, 1) << "step " << i;
      }
      unlevelledReads += rig.pilot.tracker().thetaMrad() != 0 ? 1 : 0;
      RangeReading far;
      far.status = RangeStatus::TooFar;
      far.samples = 1;
      e = DriveEvent::range(a.sensor, far);
    } else if (a.kind == DriveAction::Kind::Rotate) {
      e = DriveEvent::rotatedBy(isQuarter(a) ? a.value + 40 : 0);
    } else if (a.kind == DriveAction::Kind::Drive) {
      levelsSinceDrive = 0;
      ++drives;
      e = DriveEvent::drivenBy(a.value);
    }
    lastWasSmallRotation = a.kind == DriveAction::Kind::Rotate && !isQuarter(a);
    a = rig.pilot.step(e);
  }
  EXPECT_GE(levels, 1);  // it did try
  EXPECT_GE(unlevelledReads, 3);
  EXPECT_GE(drives, 5);
}

// Open space, exact rotations, every drive 30 mm short (after a quarter turn the robot stands 30 mm off its new
// line, so its next move is steered): until the pilot asks for a drive right after a steering rotation.
// `steer` gets that rotation (mrad); false when none came within `limit` steps.
bool untilSteeredDrive(Rig& rig, DriveAction& a, int32_t& steer, int limit = 3000) {
  bool steering = false;
  for (int i = 0; i < limit && !rig.pilot.finished(); ++i) {
    if (a.kind == DriveAction::Kind::Drive && steering) return true;
    steering = a.kind == DriveAction::Kind::Rotate && !isQuarter(a);
    if (a.kind == DriveAction::Kind::Rotate) steer = a.value;
    a = rig.pilot.step(openSpace(a, 30));
  }
  return false;
}

TEST(PilotStall, ASteeredDriveThatStallsIsDrivenAgainSquareToItsLine) {
  // A body that fits a narrow passage square to it may not fit turned by the steering: the pilot turns back
  // by what it steered and drives again; the explorer hears nothing of the first try.
  Rig rig;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  int32_t steer = 0;
  ASSERT_TRUE(untilSteeredDrive(rig, a, steer));
  ASSERT_NE(steer, 0);
  const Pose before = rig.explorer.pose();
  const int32_t theta = rig.pilot.tracker().thetaMrad();
  DriveAction back = rig.pilot.step(DriveEvent::driven(true));
  ASSERT_EQ(back.kind, DriveAction::Kind::Rotate);
  EXPECT_EQ(back.value, -steer);
  const DriveAction again = rig.pilot.step(DriveEvent::rotatedBy(-steer));
  ASSERT_EQ(again.kind, DriveAction::Kind::Drive);
  EXPECT_EQ(rig.pilot.tracker().thetaMrad(), theta - steer);  // back on the heading it had before the steering
  EXPECT_EQ(rig.explorer.counters().blockedMoves, 0u);
  rig.pilot.step(DriveEvent::drivenBy(again.value));
  EXPECT_EQ(rig.explorer.counters().blockedMoves, 0u);
  EXPECT_NE(rig.explorer.pose().cell, before.cell);  // it moved on
}

TEST(PilotStall, AnUnsteeredDriveThatStallsTooBlocksTheExplorersWay) {
  Rig rig;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  int32_t steer = 0;
  ASSERT_TRUE(untilSteeredDrive(rig, a, steer));
  const Pose before = rig.explorer.pose();
  const DriveAction back = rig.pilot.step(DriveEvent::driven(true));
  ASSERT_EQ(back.kind, DriveAction::Kind::Rotate);
  ASSERT_EQ(rig.pilot.step(DriveEvent::rotatedBy(back.value)).kind, DriveAction::Kind::Drive);
  rig.pilot.step(DriveEvent::driven(true));  // stalls again: the way is blocked
  EXPECT_EQ(rig.explorer.counters().blockedMoves, 1u);
  EXPECT_EQ(rig.explorer.pose().cell, before.cell);
}

TEST(PilotStall, AStalledStepOfTheStartsSweepEndsTheSweep) {
  PilotConfig c;
  c.squareSweepMrad = 1571;
  Rig rig(c);
  DriveAction a = rig.pilot.step(DriveEvent::start());
  ASSERT_EQ(a.kind, DriveAction::Kind::Rotate);
  a = rig.pilot.step(DriveEvent::rotatedBy(a.value));  // to the sweep's start: done
  for (int s = 0; s < kSensorCount; ++s) {
    ASSERT_EQ(a.kind, DriveAction::Kind::Read);
    a = rig.pilot.step(DriveEvent::range(a.sensor, RangeReading{}));
  }
  ASSERT_EQ(a.kind, DriveAction::Kind::Rotate);  // the first step of the sweep
  a = rig.pilot.step(DriveEvent::rotatedBy(0));  // stalls at once
  // No wall seen: back to where it was set down (the sweep's zero), a reading of each sensor for the nearest
  // walls (the snap), a think slice, then the explorer starts.
  ASSERT_EQ(a.kind, DriveAction::Kind::Rotate);
  EXPECT_EQ(a.value, 1571);
  a = rig.pilot.step(DriveEvent::rotatedBy(a.value));
  for (int s = 0; s < kSensorCount; ++s) {
    ASSERT_EQ(a.kind, DriveAction::Kind::Read);
    EXPECT_FALSE(rig.pilot.explorerStarted());
    a = rig.pilot.step(DriveEvent::range(a.sensor, RangeReading{}));
  }
  ASSERT_EQ(a.kind, DriveAction::Kind::Think);
  EXPECT_FALSE(rig.pilot.explorerStarted());
  a = rig.pilot.step(DriveEvent::thought());
  EXPECT_TRUE(rig.pilot.explorerStarted());
  EXPECT_FALSE(rig.pilot.squaring().result().found);
  EXPECT_NE(a.kind, DriveAction::Kind::Done);
}

}  // namespace
}  // namespace nxtmap
