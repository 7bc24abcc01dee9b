#pragma once
#include <cstdint>

#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"
#include "common/motion/StartSquaring.hpp"

namespace nxtmap {

// TurnCalibration: how far the robot's turns on the spot are off (the effective track width's error,
// UMBmark's Eb: every turn scaled by one factor), measured against the room's walls. Events in, actions
// out: it squares to the walls (StartSquaring), turns `turns` whole turns the other way round, and squares
// again; the second sweep finds the walls turned by the turns' error (N whole turns of 2 pi (1 + e)
// counter-clockwise leave the robot 2 pi N e past square), so e = (second sweep's estimate) / (2 pi N).
// It ends square to the walls. The turns are taken as the encoders counted them (the motor control stops each
// quarter turn a little off; with T counted, e = (the second sweep's estimate - (T - 2 pi N)) / T).
// Resolution: in a plain room the sweeps agree to about a degree, so 4 turns give e to about 0.1 %; from a
// cluttered spot they differ more (the brick rooms under nxt-uncalibrated: 0.27 % rms). |e| must stay under
// 1 / (8 N) (the walls repeat every quarter turn). A second sweep that finds no wall where the first found them
// (from the same spot, N whole turns later: a lone wall's dip seen at another angle merged with a corner's) leaves
// the robot as far past square as the turns are off, up to 30 degrees for an uncalibrated NXT: with no approach
// left to try elsewhere, it turns the whole turns back (the same error the other way), to stand square as the first
// sweep left it (turnedBack()). The sweep object is the caller's (the pilot's).
class TurnCalibration {
 public:
  // The whole turns are made in quarter turns (a turn's random error grows with its size), of
  // 1570.796 mrad rounded: 4 N of them make N whole turns to 0.8 mrad.
  static constexpr int32_t kQuarterMrad = 1571;

  TurnCalibration(StartSquaring& squaring, uint8_t turns);

  // approachesLeft: the first sweep's (StartSquaring::begin); the second sweep, from the spot where the first
  // found walls, takes the widest dip rather than none (StartSquaring::begin(0)).
  DriveAction begin(int approachesLeft = -1);
  // The answer to the previous action; returns the next. DriveAction::done() once calibrated.
  DriveAction step(const DriveEvent& e);
  bool finished() const { return phase_ == Phase::Done; }

  // Both sweeps saw the walls: errorPpm() holds the measurement.
  bool found() const { return found_; }
  // Actual turn / commanded turn - 1, parts per million (+: the robot turns too far). 0 when not found.
  int32_t errorPpm() const { return errorPpm_; }
  uint8_t turns() const { return turns_; }
  // Not found, but the first sweep squared the robot and the whole turns were turned back: square to it, off by
  // the turns' random error and the gears' play at the reversals (a few degrees).
  bool turnedBack() const { return turnedBack_; }

 private:
  enum class Phase : uint8_t { Idle, FirstSweep, Turning, SecondSweep, TurningBack, Done };

  DriveAction afterFirstSweep();
  void measure();

  StartSquaring& squaring_;
  uint8_t turns_;
  uint8_t quartersLeft_ = 0;
  Phase phase_ = Phase::Idle;
  bool found_ = false;
  bool lastTry_ = false;  // begin() was told no approach is left
  bool turnedBack_ = false;
  int32_t errorPpm_ = 0;
  // Spent before the sweep in progress (the first sweep once done, and the whole turns).
  uint32_t readings_ = 0, samples_ = 0, turnedMrad_ = 0;
  bool sweeping_ = false;  // squaring_ holds a sweep of this calibration not yet added above
  // The whole turns as the encoders counted them (mrad, counter-clockwise positive; the commanded angle for a
  // rotation not measured): the motors stop a little past or short of each quarter, and that is no turn error.
  int32_t countedMrad_ = 0;

 public:
  // Readings, raw samples and rotation (mrad) spent, for the run's figures.
  uint32_t readings() const { return readings_ + (sweeping_ ? squaring_.readings() : 0); }
  uint32_t samples() const { return samples_ + (sweeping_ ? squaring_.samples() : 0); }
  uint32_t turnedMrad() const { return turnedMrad_ + (sweeping_ ? squaring_.turnedMrad() : 0); }
};

}  // namespace nxtmap
