// TurnCalibration, events in and actions out, in a room of two walls: the turn error measured between two sweeps
// with whole turns between them, the turns taken as the encoders counted them, and a second sweep that finds no
// wall turned back.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "common/motion/StartSquaring.hpp"
#include "common/motion/TurnCalibration.hpp"
#include "tests/common/SweptWalls.hpp"

namespace nxtmap {
namespace {

using sweptwalls::kPi;
using sweptwalls::TwoWalls;

// A turn calibration of 4 whole turns in TwoWalls with the right wall 40 cm away, begun with `approachesLeft`
// (0: the pilot's last sweep), the wheels turning (1 + errorPpm / 10^6) times what the encoders count and the
// motors stopping pastMrad past each rotation asked for (counted so). `secondSweepSees` false: the walls give no
// echo once the whole turns are made (the second sweep finds nothing where the first found them).
struct CalibrationOutcome {
  bool finished = false, found = false;
  int32_t errorPpm = 0;
  bool turnedBack = false;
  int64_t trueMrad = 0;  // where the robot truly faces at the end, from where it began (+ clockwise)
};
CalibrationOutcome calibrateBetweenTwoWalls(int32_t errorPpm, int32_t pastMrad, int approachesLeft = 0,
                                            bool secondSweepSees = true) {
  TwoWalls room;
  room.rightCm = 40;
  StartSquaring squaring;
  TurnCalibration calibration(squaring, 4);
  int64_t countedMrad = 0;  // every turn as counted, summed; the robot has truly turned (1 + e) times that
  DriveAction a = calibration.begin(approachesLeft);
  for (int i = 0; i < 2000 && !calibration.finished(); ++i) {
    if (a.kind == DriveAction::Kind::Rotate) {
      const int32_t counted = a.value + (a.value < 0 ? -pastMrad : pastMrad);
      countedMrad += counted;
      a = calibration.step(DriveEvent::rotatedBy(counted));
      continue;
    }
    EXPECT_EQ(a.kind, DriveAction::Kind::Read);
    if (a.kind != DriveAction::Kind::Read) break;
    RangeReading r;
    r.cm = room.read(a.sensor, static_cast<int32_t>(countedMrad * (1000000 + errorPpm) / 1000000));
    if (!secondSweepSees && countedMrad < -20000) r.cm = 0;  // past the whole turns
    r.status = r.cm > 0 ? RangeStatus::Good : RangeStatus::NoEcho;
    r.samples = 1;
    a = calibration.step(DriveEvent::range(a.sensor, r));
  }
  return CalibrationOutcome{calibration.finished(), calibration.found(), calibration.errorPpm(),
                            calibration.turnedBack(), countedMrad * (1000000 + errorPpm) / 1000000};
}

// A turn calibration where only the widest dip names the walls (the two walls 6 degrees apart, nothing 70 cm away
// to approach): its first sweep is the pilot's last (no approach left) and takes that dip; the second sweep, after
// the whole turns, stands where the first did and takes it too (begun as a sweep that never takes it, it found no
// wall and the turns went unmeasured). The wheels turn 1 % too far and the encoders count what was told.
TEST(TurnCalibration, TheSecondSweepTakesTheWidestDipWhereTheFirstDid) {
  constexpr int32_t kErrorPpm = 10000;
  const CalibrationOutcome c = calibrateBetweenTwoWalls(kErrorPpm, 0);
  ASSERT_TRUE(c.finished);
  ASSERT_TRUE(c.found);
  EXPECT_NEAR(c.errorPpm, kErrorPpm, 2000);  // measured 1.11 %: the two sweeps place the dip 27 mrad apart
}

// The motors stop each quarter turn a little past or short of it, and the encoders count where they stopped:
// that is no turn error. The whole turns are taken as counted (told alone, 8 mrad past each of 16 quarters
// would read as 0.5 % more).
TEST(TurnCalibration, TheTurnsAreTakenAsTheEncodersCountedThem) {
  constexpr int32_t kErrorPpm = 10000;
  for (const int32_t pastMrad : {0, 8, -8}) {
    const CalibrationOutcome c = calibrateBetweenTwoWalls(kErrorPpm, pastMrad);
    ASSERT_TRUE(c.finished) << pastMrad;
    ASSERT_TRUE(c.found) << pastMrad;
    EXPECT_NEAR(c.errorPpm, kErrorPpm, 2000) << "stopping " << pastMrad << " mrad past each quarter";
  }
}

// The second sweep finds no wall where the first found them (the turns 2 % off: 4 whole turns leave the robot 29
// degrees past square). As the pilot's last sweep (no approach left) the calibration turns the whole turns back,
// the same error the other way: it ends square to the walls the first sweep saw (the front's, 3 degrees), in the
// whole turn it began in. With an approach left it ends where the second sweep began, for the pilot to approach.
TEST(TurnCalibration, ASecondSweepThatFindsNoWallIsTurnedBackWhenNoApproachIsLeft) {
  struct Row {
    int approachesLeft;
    bool secondSweepSees;
    bool found, turnedBack;
    int wholeTurns;  // where it ends, in whole turns from where it began
    bool square;     // within 2 degrees of the front's wall normal
  };
  const Row rows[] = {
      {0, true, true, false, -4, true},     // measured: square as the second sweep found the walls
      {0, false, false, true, 0, true},     // turned back: square as the first sweep left it
      {2, false, false, false, -4, false},  // left for an approach: 4 turns' error past square
      {2, true, true, false, -4, true},
  };
  constexpr int32_t kErrorPpm = 20000;
  for (const Row& row : rows) {
    const CalibrationOutcome c = calibrateBetweenTwoWalls(kErrorPpm, 0, row.approachesLeft, row.secondSweepSees);
    const std::string what = "approaches left " + std::to_string(row.approachesLeft) +
                             (row.secondSweepSees ? ", second sweep sees" : ", second sweep blind");
    ASSERT_TRUE(c.finished) << what;
    EXPECT_EQ(c.found, row.found) << what;
    EXPECT_EQ(c.turnedBack, row.turnedBack) << what;
    const double turns = static_cast<double>(c.trueMrad) / (2000.0 * kPi);
    EXPECT_EQ(std::lround(turns), row.wholeTurns) << what;
    const double offDeg = std::remainder(c.trueMrad * 0.18 / kPi - 3.0, 360.0);
    EXPECT_EQ(std::fabs(offDeg) < 2.0, row.square) << what << ": " << offDeg << " deg off the wall's normal";
  }
}

}  // namespace
}  // namespace nxtmap
