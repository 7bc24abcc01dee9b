// The pilot against scripted wheels and sensors: every explorer reading is taken on the axis
// the explorer marks it along, even when a turn ended off its target (as the brick's encoders
// report it) or a move was steered towards a cell centre.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "common/explore/ExplorerStorage.hpp"
#include "common/explore/FrontierExplorer.hpp"
#include "common/motion/Pilot.hpp"
#include "tests/common/PilotRoomRig.hpp"

namespace nxtmap {
namespace {
using pilotrig::noisyWheels;
using pilotrig::rangeToWalls;
using pilotrig::Rig;
using pilotrig::RoomRun;
using pilotrig::runInRoom;
using pilotrig::Wheels;

// Distance in mrad from `urad` (microradians) to the nearest multiple of a quarter turn.
int32_t offAxisMrad(int64_t urad) {
  const int64_t q = 1570796;
  int64_t r = urad % q;
  if (r < 0) r += q;
  if (r > q / 2) r -= q;
  return static_cast<int32_t>((r < 0 ? -r : r) / 1000);
}

TEST(Pilot, LevelsAKnownHeadingErrorBeforeEachExplorerReading) {
  Rig rig;
  // Open space, nothing in range. As the encoders report it: every turn of a quarter or more
  // ends 35 mrad past its target, every drive 6 mm short (so after a turn the next move steers
  // towards the cell centre beside it); small rotations are exact.
  int64_t headingUrad = 0;  // the robot's real heading, + clockwise
  int readsChecked = 0, errorsMade = 0;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  for (int i = 0; i < 3000 && !rig.pilot.finished(); ++i) {
    DriveEvent e = DriveEvent::thought();
    switch (a.kind) {
      case DriveAction::Kind::Read: {
        EXPECT_LE(offAxisMrad(headingUrad), PilotConfig{}.minRotateMrad) << "reading " << readsChecked;
        ++readsChecked;
        RangeReading r;
        r.status = RangeStatus::TooFar;
        r.samples = 1;
        e = DriveEvent::range(a.sensor, r);
        break;
      }
      case DriveAction::Kind::Rotate: {
        const bool quarter = std::abs(a.value) > 700;
        const int32_t achieved = a.value + (quarter ? 35 : 0);
        errorsMade += quarter ? 1 : 0;
        headingUrad += static_cast<int64_t>(achieved) * 1000;
        e = DriveEvent::rotatedBy(achieved);
        break;
      }
      case DriveAction::Kind::Drive: e = DriveEvent::drivenBy(a.value > 0 ? a.value - 6 : a.value + 6); break;
      case DriveAction::Kind::Think:
      case DriveAction::Kind::Done: break;
    }
    a = rig.pilot.step(e);
  }
  EXPECT_GT(errorsMade, 2);  // the script did turn the robot off its axis
  EXPECT_GT(readsChecked, 20);
}

// A corridor 0.7 m wide and 5.2 m long (x from -250 to 450 mm, y from -250 to 4950 mm), robot at the origin facing North (+y), clockwise headings. Every
// quarter turn ends 25 mrad past its target (the encoders do not see it: a wheelbase a little off);
// smaller rotations and drives are exact. Returns the mean |true - estimated heading| (mrad) over
// the explorer's readings.
double meanHeadingErrorInACorridor(const PilotConfig& config, int& readings, double startErrorRad = 0) {
  Rig rig(config);
  double x = 0, y = 0;       // mm
  double h = startErrorRad;  // rad, clockwise from North
  // Walls on cell faces (cells are 100 mm, centred on multiples of 100).
  const double west = -250, east = 450, south = -250, north = 4950;
  const auto rangeMm = [&](double a) { return rangeToWalls(west, east, south, north, x, y, a); };
  double sum = 0;
  readings = 0;
  DriveAction a = rig.pilot.step(DriveEvent::start());
  for (int i = 0; i < 6000 && !rig.pilot.finished(); ++i) {
    DriveEvent e = DriveEvent::thought();
    switch (a.kind) {
      case DriveAction::Kind::Read: {
        const double axis = static_cast<int>(rig.explorer.pose().heading) * 1.5707963;
        const double err = std::remainder(h - axis, 6.2831853) * 1000.0 - rig.pilot.tracker().thetaMrad();
        sum += std::fabs(err);
        ++readings;
        RangeReading r;
        const double mm = rangeMm(h + static_cast<int>(a.sensor) * 1.5707963);
        r.samples = 3;
        if (mm > 1000) {
          r.status = RangeStatus::TooFar;
        } else {
          r.status = RangeStatus::Good;
          r.cm = static_cast<uint8_t>(std::lround(mm / 10.0));
        }
        e = DriveEvent::range(a.sensor, r);
        break;
      }
      case DriveAction::Kind::Rotate: {
        const bool quarter = std::abs(a.value) > 700;
        h += a.value / 1000.0 + (quarter ? 0.025 : 0.0);
        e = DriveEvent::rotatedBy(a.value);  // the encoders report the command
        break;
      }
      case DriveAction::Kind::Drive:
        x += a.value * std::sin(h);
        y += a.value * std::cos(h);
        e = DriveEvent::drivenBy(a.value);
        break;
      case DriveAction::Kind::Think:
      case DriveAction::Kind::Done: break;
    }
    a = rig.pilot.step(e);
  }
  return readings == 0 ? 0.0 : sum / readings;
}

TEST(Pilot, StraightWallsBesideTheRunMeasureTheHeadingError) {
  // No wall of the map is trusted as a landmark (as on a first visit, when the walls beside the
  // run are being mapped from the very pose that drifts): only pairs of side readings can tell.
  PilotConfig on;
  on.minWallEvidence = 127;
  PilotConfig off = on;
  off.sideReadEveryMm = 0;
  off.sideBaseMm = 1 << 20;  // never a pair: no heading from the side walls
  int nOn = 0, nOff = 0;
  const double withSides = meanHeadingErrorInACorridor(on, nOn);
  const double without = meanHeadingErrorInACorridor(off, nOff);
  ASSERT_GT(nOn, 20);
  ASSERT_GT(nOff, 20);
  EXPECT_LT(withSides, without / 2) << "with side walls " << withSides << " mrad, without " << without << " mrad";
}

TEST(Pilot, AHeadingHandedOverWithItsUncertaintyIsCorrectedByTheSideWalls) {
  // The robot is handed over 70 mrad off the axis (the last pilot's levelling missed by that much).
  // Told how uncertain the heading is, the pilot takes the side walls' slope of 70 mrad as a
  // heading error; told it is exact, it takes that slope for another wall and keeps the error.
  // The robot's store says its turns are right to 0.1 % (they are 1.6 % off): it does not learn them soon.
  PilotConfig handed;
  handed.minWallEvidence = 127;  // only the side pairs can tell (as in the corridor test above)
  handed.startHeadingVarianceMrad2 = 60 * 60;
  handed.wheels = Wheels::calibrated();
  handed.noise.readingMm = 3;  // the corridor's readings are exact but for the whole cm, and the tracker is told so
  PilotConfig exact = handed;
  exact.startHeadingVarianceMrad2 = 0;
  int nHanded = 0, nExact = 0;
  const double withUncertainty = meanHeadingErrorInACorridor(handed, nHanded, 0.070);
  const double without = meanHeadingErrorInACorridor(exact, nExact, 0.070);
  ASSERT_GT(nHanded, 20);
  ASSERT_GT(nExact, 20);
  EXPECT_LT(withUncertainty, without / 2)
      << "handed over with its uncertainty " << withUncertainty << " mrad, as exact " << without << " mrad";
  // A store that says nothing (an uncalibrated robot's defaults): the turns' error is learnt from the side
  // walls, and with it the heading is found even when it was handed over as exact.
  PilotConfig learning = exact;
  learning.wheels = WheelCalibration{};
  int nLearning = 0;
  const double learnt = meanHeadingErrorInACorridor(learning, nLearning, 0.070);
  ASSERT_GT(nLearning, 20);
  EXPECT_LT(learnt, without / 10) << "learning the turns " << learnt << " mrad, as exact " << without << " mrad";
}

TEST(Pilot, FarEchoesOfKnownWallsHoldThePositionInTheMiddleOfALargeRoom) {
  // 4.1 m square: from its middle no wall is within the 1 m the explorer maps with, but the walls
  // it mapped on the way are within 2 m. Both steer at every cell (the steering dead band has its
  // own test below), so only the far echoes differ. Summed over 10 runs of each of 4 wheel errors (single
  // runs are chaotic).
  PilotConfig far;
  far.steerAboveMm = 0;
  PilotConfig near = far;
  near.poseRangeCm = 0;
  const struct { int slipPerMille, turnMrad; } table[] = {{40, 10}, {40, 20}, {60, 10}, {60, 20}};
  double sumFar = 0, sumNear = 0;
  int wrongFar = 0, wrongNear = 0;
  for (const auto& row : table) {
    for (uint32_t run = 1; run <= 10; ++run) {
      Wheels w;
      w.slipPerMille = row.slipPerMille;
      w.turnMrad = row.turnMrad;
      w.seed = run * 7919;
      const RoomRun withFar = runInRoom(far, -2050, 2050, -2050, 2050, w);
      const RoomRun without = runInRoom(near, -2050, 2050, -2050, 2050, w);
      ASSERT_GT(withFar.readings, 100);
      ASSERT_GT(without.readings, 100);
      sumFar += withFar.meanEstimateErrorMm / 40;
      sumNear += without.meanEstimateErrorMm / 40;
      wrongFar += withFar.wrongCells;
      wrongNear += without.wrongCells;
    }
  }
  std::printf("with far echoes %.1f mm, %d wrong cells; without %.1f mm, %d\n", sumFar, wrongFar, sumNear, wrongNear);
  EXPECT_LT(sumFar, 0.8 * sumNear) << "with far echoes " << sumFar << " mm, without " << sumNear << " mm";
  EXPECT_LE(wrongFar, wrongNear);
}

TEST(Pilot, SmallOffsetsFromTheCentreLineAreNotSteeredOut) {
  // Every rotation errs, small ones too (backlash, wheel scrub), drives slip and echoes are noisy, so
  // the believed offset from the centre line jitters by a few mm. Steering back to the line at every
  // cell chases that jitter with two small rotations (steer, then level), each adding heading error;
  // with the dead band the robot drives on along a line a few mm off it. Summed over 100 runs each
  // (single runs are chaotic; 10 runs swing the sums by a third): under half the rotations, for a
  // position known as well and as few wrong cells (within the 100 runs' spread, 20 %).
  const struct { int slipPerMille, turnMrad; } table[] = {{17, 15}, {30, 15}};
  PilotConfig everyCell;
  everyCell.steerAboveMm = 0;
  int rotations[2] = {0, 0}, wrong[2] = {0, 0};
  double positionMm[2] = {0, 0};
  for (const auto& row : table) {
    for (uint32_t run = 1; run <= 100; ++run) {
      const Wheels w = noisyWheels(row.slipPerMille, row.turnMrad, run);
      for (int k = 0; k < 2; ++k) {
        const RoomRun r = runInRoom(k == 0 ? PilotConfig{} : everyCell, -2050, 2050, -1550, 1550, w);
        ASSERT_GT(r.readings, 100);
        rotations[k] += r.smallRotations;
        wrong[k] += r.wrongCells;
        positionMm[k] += r.meanEstimateErrorMm / 100;
      }
    }
  }
  EXPECT_LT(rotations[0] * 2, rotations[1]);
  EXPECT_LT(positionMm[0], 1.2 * positionMm[1]);
  EXPECT_LT(wrong[0], 1.2 * wrong[1]);
  std::printf("small rotations %d against %d, position error %.1f against %.1f mm, wrong cells %d against %d\n",
              rotations[0], rotations[1], positionMm[0] / 2, positionMm[1] / 2, wrong[0], wrong[1]);
}

TEST(Pilot, AStraightWallFacePullsBackADriftAcrossOpenSpace) {
  // 6.1 m square: crossing its middle no wall is within the 2.5 m pose range, so an unseen turn
  // error becomes a sideways drift. Back in range, a straight wall face corrects it even beyond the
  // 40 mm gate (PoseNoise::wideGateMm) when the filter itself is that unsure. Summed over 20 runs
  // each (single runs are chaotic): the position is known better than with the ordinary gate alone.
  const struct { int slipPerMille, turnMrad; } table[] = {{17, 15}, {17, 25}, {30, 25}};
  PilotConfig narrow;
  narrow.noise.wideGateMm = 0;
  for (const auto& row : table) {
    double wide = 0, ordinary = 0;
    for (uint32_t run = 1; run <= 20; ++run) {
      const Wheels w = noisyWheels(row.slipPerMille, row.turnMrad, run);
      wide += runInRoom(PilotConfig{}, -3050, 3050, -3050, 3050, w).meanEstimateErrorMm / 20;
      ordinary += runInRoom(narrow, -3050, 3050, -3050, 3050, w).meanEstimateErrorMm / 20;
    }
    EXPECT_LT(wide, ordinary) << "slip " << row.slipPerMille << " turn " << row.turnMrad;
    std::printf("slip %d turn %d: position error %.1f mm with straight faces trusted further, %.1f without\n",
                row.slipPerMille, row.turnMrad, wide, ordinary);
  }
}

TEST(Pilot, ASecondStraightFaceConfirmsAnOffsetTheFilterWasTooSureToTake) {
  // A sure filter (every wall read, nothing slips) and one unseen shove East, most of a cell, after
  // the given drive: the walls East and West now read `kick` mm off, beyond the 40 mm gate and far
  // beyond 2 sigma. Refused for good, the rest of the room is mapped from the wrong offset; a second
  // straight face agreeing with the first refusal is taken (PoseNoise::confirmWide). The shoves come
  // once the side walls are mapped: a shove before that is mapped into them and cannot be seen.
  const struct {
    int after;
    int32_t kick;
  } table[] = {{6, 90}, {6, -80}, {10, -70}, {15, 80}, {20, -90}};
  PilotConfig once;
  once.noise.confirmWide = false;
  for (const auto& row : table) {
    Wheels w;
    w.kickAfterDrive = row.after;
    w.kickEastMm = row.kick;
    const RoomRun confirmed = runInRoom(PilotConfig{}, -750, 850, -650, 950, w);
    const RoomRun refused = runInRoom(once, -750, 850, -650, 950, w);
    EXPECT_LT(confirmed.meanEstimateErrorMm, refused.meanEstimateErrorMm / 2)
        << "kick " << row.kick << " after " << row.after;
    EXPECT_LT(confirmed.wrongCells, refused.wrongCells) << "kick " << row.kick << " after " << row.after;
    std::printf("kick %d mm after drive %d: position error %.1f mm, %d wrong cells; refused for good %.1f mm, %d\n",
                row.kick, row.after, confirmed.meanEstimateErrorMm, confirmed.wrongCells, refused.meanEstimateErrorMm,
                refused.wrongCells);
  }
}

TEST(Pilot, OnTwentyCentimetreCellsAnUnseenShoveOfAQuarterCellIsTakenFromTheNextWall) {
  // The brick's 20 cm cells: a shove East of 50-55 mm, unseen (beyond the 40 mm gate, within 3/10 of a cell:
  // PilotConfig::gateCellTenths), is corrected by the next reading of a known wall; with the 40 mm gate alone
  // it is refused and the robot maps on from the wrong offset. No second straight face rescues either
  // (PoseNoise::confirmWide off in both).
  ExplorerConfig brick;
  brick.geometry.cellCm = 20;
  PilotConfig tenths;
  tenths.noise.confirmWide = false;
  PilotConfig fixed = tenths;
  fixed.gateCellTenths = 0;
  const struct {
    int after;
    int32_t kick;
  } table[] = {{6, 50}, {10, -55}, {15, 50}, {20, -50}};
  for (const auto& row : table) {
    Wheels w;
    w.kickAfterDrive = row.after;
    w.kickEastMm = row.kick;
    const RoomRun taken = runInRoom(tenths, -1500, 1700, -1300, 1900, w, brick);
    const RoomRun refused = runInRoom(fixed, -1500, 1700, -1300, 1900, w, brick);
    ASSERT_GT(taken.readings, 20);
    EXPECT_LT(taken.lateEstimateErrorMm, refused.lateEstimateErrorMm / 4)
        << "kick " << row.kick << " after " << row.after;
    EXPECT_LE(taken.wrongCells, refused.wrongCells) << "kick " << row.kick << " after " << row.after;
    std::printf(
        "kick %d mm after drive %d: position error %.1f mm (second half %.1f), %d wrong cells; 40 mm gate %.1f "
        "mm (%.1f), %d\n",
        row.kick, row.after, taken.meanEstimateErrorMm, taken.lateEstimateErrorMm, taken.wrongCells,
        refused.meanEstimateErrorMm, refused.lateEstimateErrorMm, refused.wrongCells);
  }
}

TEST(Pilot, ReadingsAreMarkedFromTheCellCentreWhenTheRobotIsKnownToBeOffIt) {
  // Every drive stops 60 mm short and the encoders say so: at each reading the robot stands 60 mm
  // behind the centre of its cell (the next move makes up for it). Marked from where the robot
  // stands, echoes ahead would fall a cell too far.
  PilotConfig off;
  off.centreReadings = false;
  Wheels wheels;
  wheels.shortMm = 60;
  const RoomRun centred = runInRoom(PilotConfig{}, -750, 850, -650, 950, wheels);
  const RoomRun asRead = runInRoom(off, -750, 850, -650, 950, wheels);
  ASSERT_GT(centred.readings, 20);
  EXPECT_EQ(centred.wrongCells, 0);
  EXPECT_GT(asRead.wrongCells, 0);
}

}  // namespace
}  // namespace nxtmap

namespace nxtmap {
namespace {

// A known turn error (PilotConfig::wheels): every rotation is told divided by 1 + e, and what the
// encoders count (what was told) is heard multiplied by it, so the pilot's own angles stay true.
TEST(Pilot, CorrectsEveryTurnByTheKnownTurnError) {
  PilotConfig c;
  c.squareSweepMrad = 1571;  // the start's sweep: its first action is a rotation
  const struct {
    int32_t ppm;
    int32_t firstTold;  // -1571 / (1 + e)
    int32_t stepTold;   // 87 / (1 + e)
  } table[] = {{0, -1571, 87}, {20000, -1540, 85}, {-20000, -1603, 88}, {100000, -1428, 79}};
  for (const auto& t : table) {
    c.wheels.turnPpm = t.ppm;
    Rig rig(c);
    const DriveAction first = rig.pilot.step(DriveEvent::start());
    ASSERT_EQ(first.kind, DriveAction::Kind::Rotate);
    EXPECT_EQ(first.value, t.firstTold) << t.ppm;
    // The encoders count what was told; the sweep then reads its four sensors at that heading.
    DriveAction a = rig.pilot.step(DriveEvent::rotatedBy(first.value));
    for (int s = 0; s < kSensorCount; ++s) {
      ASSERT_EQ(a.kind, DriveAction::Kind::Read) << t.ppm;
      RangeReading none;
      a = rig.pilot.step(DriveEvent::range(a.sensor, none));
    }
    ASSERT_EQ(a.kind, DriveAction::Kind::Rotate);
    EXPECT_EQ(a.value, t.stepTold) << t.ppm;
    EXPECT_EQ(rig.pilot.turnErrorPpm(), t.ppm);
  }
}

}  // namespace
}  // namespace nxtmap
