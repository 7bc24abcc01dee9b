#include "common/motion/TurnCalibration.hpp"

#include "common/check/Check.hpp"

namespace nxtmap {

TurnCalibration::TurnCalibration(StartSquaring& squaring, uint8_t turns) : squaring_(squaring), turns_(turns) {
  NXTMAP_CHECK(turns <= 8);  // 0: not used (begin() needs at least one)
}

DriveAction TurnCalibration::begin(int approachesLeft) {
  NXTMAP_CHECK(turns_ >= 1);
  found_ = turnedBack_ = false;
  lastTry_ = approachesLeft <= 0;
  errorPpm_ = 0;
  readings_ = samples_ = turnedMrad_ = 0;
  countedMrad_ = 0;
  phase_ = Phase::FirstSweep;
  sweeping_ = true;
  return squaring_.begin(approachesLeft);
}

DriveAction TurnCalibration::afterFirstSweep() {
  readings_ = squaring_.readings();
  samples_ = squaring_.samples();
  turnedMrad_ = squaring_.turnedMrad();
  sweeping_ = false;
  if (!squaring_.result().found) {  // no walls to measure against: the turns would tell nothing
    phase_ = Phase::Done;
    return DriveAction::done();
  }
  phase_ = Phase::Turning;
  quartersLeft_ = static_cast<uint8_t>(4 * turns_);
  return DriveAction::rotate(-kQuarterMrad);  // counter-clockwise: the sweep ended turning clockwise
}

void TurnCalibration::measure() {
  const WallDirectionEstimate& w = squaring_.result();
  found_ = w.found;
  if (!found_) return;
  // The walls seen w.mrad clockwise of the robot after turning T (counted) counter-clockwise, truly T (1 + e):
  // the robot stands T (1 + e) - 2 pi N counter-clockwise of square, so w.mrad = (T - 2 pi N) + T e.
  constexpr int64_t kTwoPiUrad = 6283185;
  const int64_t countedUrad = static_cast<int64_t>(countedMrad_) * 1000;
  const int64_t pastUrad = countedUrad - kTwoPiUrad * turns_;
  errorPpm_ = static_cast<int32_t>((static_cast<int64_t>(w.mrad) * 1000 - pastUrad) * 1000000 / countedUrad);
}

DriveAction TurnCalibration::step(const DriveEvent& e) {
  switch (phase_) {
    case Phase::FirstSweep: {
      const DriveAction a = squaring_.step(e);
      return squaring_.finished() ? afterFirstSweep() : a;
    }
    case Phase::Turning:
    case Phase::TurningBack:  // (counted as well, after the measurement: no matter)
      NXTMAP_CHECK(e.kind == DriveEvent::Kind::Rotated);
      turnedMrad_ += kQuarterMrad;
      countedMrad_ += e.measured ? -e.achieved : kQuarterMrad;
      if (--quartersLeft_ > 0) return DriveAction::rotate(phase_ == Phase::Turning ? -kQuarterMrad : kQuarterMrad);
      if (phase_ == Phase::TurningBack) {
        turnedBack_ = true;
        break;
      }
      phase_ = Phase::SecondSweep;
      sweeping_ = true;
      return squaring_.begin(0);  // the walls the first sweep saw are there: the widest dip alone rather than none
    case Phase::SecondSweep: {
      const DriveAction a = squaring_.step(e);
      if (!squaring_.finished()) return a;
      measure();
      if (!found_ && lastTry_) {  // the sweep ended where it began, the whole turns past square: turn them back
        phase_ = Phase::TurningBack;
        quartersLeft_ = static_cast<uint8_t>(4 * turns_);
        return DriveAction::rotate(kQuarterMrad);
      }
      break;
    }
    case Phase::Idle:
    case Phase::Done: NXTMAP_CHECK(false);  // an event that does not answer the action in progress: a caller's mistake
  }
  phase_ = Phase::Done;
  return DriveAction::done();
}

}  // namespace nxtmap
