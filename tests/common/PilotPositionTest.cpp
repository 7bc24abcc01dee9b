// The pilot's position in scripted rooms (PilotRoomRig): far echoes of known walls, the steering dead band,
// straight wall faces taking offsets beyond the gate, and readings marked from the cell centre.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>

#include "common/motion/Pilot.hpp"
#include "tests/common/PilotRoomRig.hpp"

namespace nxtmap {
namespace {
using pilotrig::noisyWheels;
using pilotrig::RoomRun;
using pilotrig::runInRoom;
using pilotrig::Wheels;

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
