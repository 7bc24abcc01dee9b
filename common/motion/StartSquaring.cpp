#include "common/motion/StartSquaring.hpp"

#include "common/check/Check.hpp"
#include "common/math/IntAbs.hpp"

namespace nxtmap {
namespace {

// An angle (mrad) brought into (-pi, pi].
int32_t withinHalfTurn(int32_t mrad) {
  while (mrad > 2 * WallDirection::kQuarterMrad) mrad -= 4 * WallDirection::kQuarterMrad;
  while (mrad <= -2 * WallDirection::kQuarterMrad) mrad += 4 * WallDirection::kQuarterMrad;
  return mrad;
}

// A reading's range for the sweep: an echo within the trusted range, or one beyond it the samples agree
// on (RangeReading::cm of TooFar); 0 for no echo, too near or inconsistent.
int16_t sweepCm(const RangeReading& r) {
  if (r.status == RangeStatus::Good || r.status == RangeStatus::TooFar) return r.cm;
  return 0;
}

}  // namespace

StartSquaring::StartSquaring(int32_t sweepMrad, int32_t stepMrad, int16_t approachFromCm, int32_t coneHalfMrad)
    : sweepMrad_(sweepMrad), stepMrad_(stepMrad), approachFromCm_(approachFromCm), walls_(coneHalfMrad) {
  NXTMAP_CHECK(stepMrad > 0 && sweepMrad >= 0 && 2 * sweepMrad / stepMrad < WallDirection::kMaxSteps);
}

DriveAction StartSquaring::begin(int approachesLeft) {
  approachesLeft_ = static_cast<int8_t>(approachesLeft < 0 ? -1 : (approachesLeft > 100 ? 100 : approachesLeft));
  walls_.clear();
  result_ = WallDirectionEstimate{};
  headingMrad_ = targetMrad_ = 0;
  readings_ = samples_ = turnedMrad_ = 0;
  stalled_ = false;
  target_ = Echo{};
  heard_ = false;
  return turn(Phase::ToStart, -sweepMrad_);
}

DriveAction StartSquaring::turn(Phase next, int32_t mrad) {
  phase_ = next;
  commandMrad_ = mrad;
  turnedMrad_ += static_cast<uint32_t>(abs32(mrad));
  return DriveAction::rotate(mrad);
}

DriveAction StartSquaring::readNext() {
  if (sensor_ < kSensorCount) {
    phase_ = Phase::Read;
    return DriveAction::read(static_cast<Sensor>(sensor_));
  }
  // Every sensor read at this heading: the next one, or the end of the sweep (a last step would pass
  // +sweep by more than half a step).
  if (!stalled_ && headingMrad_ + stepMrad_ <= sweepMrad_ + stepMrad_ / 2 && walls_.steps() < WallDirection::kMaxSteps)
    return turn(Phase::Step, stepMrad_);
  result_ = walls_.estimate();
  if (!result_.found && approachesLeft_ >= 0 && (approachesLeft_ == 0 || !target_.seen)) {
    const uint8_t dips = result_.dips;
    result_ = walls_.widestWall();  // the last sweep: a wall alone rather than none
    result_.dips = dips;
  }
  targetMrad_ = result_.found ? result_.mrad : 0;
  return turn(Phase::ToWalls, targetMrad_ - headingMrad_);
}

void StartSquaring::noteEcho(Sensor s, int16_t cm) {
  if (cm < approachFromCm_) return;
  const bool farthest = avoiding_;  // see approachEcho()
  if (farthest && cm > kFarthestCm) return;
  if (target_.seen && (farthest ? cm <= target_.cm : cm >= target_.cm)) return;
  const int32_t mrad = withinHalfTurn(headingMrad_ + static_cast<int32_t>(s) * WallDirection::kQuarterMrad);
  if (avoiding_ && abs32(withinHalfTurn(mrad - avoidMrad_)) < 2 * WallDirection::kQuarterMrad / 3) return;
  target_ = Echo{true, mrad, cm};
}

DriveAction StartSquaring::step(const DriveEvent& e) {
  switch (phase_) {
    case Phase::ToStart:
    case Phase::Step:
    case Phase::ToWalls:
      if (e.kind != DriveEvent::Kind::Rotated) break;
      {
        const int32_t got = e.measured ? e.achieved : commandMrad_;
        headingMrad_ += got;
        if (phase_ == Phase::ToWalls) {
          phase_ = Phase::Done;
          return DriveAction::done();
        }
        if (2 * abs32(got) < abs32(commandMrad_)) {  // stalled: estimate from the headings read so far
          stalled_ = true;
          sensor_ = kSensorCount;
          return readNext();
        }
      }
      walls_.addHeading(headingMrad_);
      sensor_ = 0;
      return readNext();
    case Phase::Read:
      if (e.kind != DriveEvent::Kind::Range || static_cast<uint8_t>(e.sensor) != sensor_) break;
      walls_.addReading(e.sensor, sweepCm(e.reading));
      noteEcho(e.sensor, sweepCm(e.reading));
      heard_ = heard_ || sweepCm(e.reading) > 0 || e.reading.status == RangeStatus::TooNear;
      ++readings_;
      samples_ += e.reading.samples;
      ++sensor_;
      return readNext();
    case Phase::Idle:
    case Phase::Done: break;
  }
  NXTMAP_CHECK(false);  // an event that does not answer the action in progress: a caller's mistake
  return DriveAction::done();
}

}  // namespace nxtmap
