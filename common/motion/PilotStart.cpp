// The pilot's start (sweep to the walls, turn calibration) and the turn correction around every step.
#include "common/check/Check.hpp"
#include "common/motion/Pilot.hpp"

namespace nxtmap {
namespace {
// How well a turn calibration measures the turn error (1 sigma, ppm; TurnCalibration: about 0.2 %).
constexpr int64_t kCalibratedTurnPpm = 3000;
// How well the heading is known after a calibration turned its whole turns back (1 sigma, mrad): the first sweep's
// squaring, then the random error of 8 N quarter turns and the gears' play at the reversals.
constexpr int64_t kTurnedBackHeadingMrad = 50;
}  // namespace

DriveAction Pilot::startExplorer(int64_t headingVarianceMrad2) {
  tracker_.reset(headingVarianceMrad2);
#ifndef NXTMAP_NO_START_SQUARING
  tracker_.place(snapMm_[0], snapMm_[1]);
#endif
  readHere_ = 0;
  sides_.clear();  // a new start: the walls read before are in another frame
  startRun();
  return begin(explorer_.step(Event::startAt(startPose_)));
}

DriveAction Pilot::square(const DriveEvent& e) {
#ifdef NXTMAP_NO_START_SQUARING
  (void)e;
  NXTMAP_CHECK(false);  // never in Phase::Square without the sweep
  return DriveAction::done();
#else
  if (config_.calibrateTurns > 0 && !calibration_.finished()) {
    const DriveAction a = calibration_.step(e);
    if (!calibration_.finished()) return a;
    countSweep(calibration_);
    if (calibration_.found()) {
      turnErrorPpm_ += calibration_.errorPpm();
      tracker_.knowTurn(kCalibratedTurnPpm * kCalibratedTurnPpm);
    } else {
      approachIfFar();  // the calibration's first sweep saw no straight wall: as below
      if (phase_ == Phase::Approach) return DriveAction::rotate(commandMrad_);
    }
  } else {
    const DriveAction a = squaring_.step(e);
    if (!squaring_.finished()) return a;
    countSweep(squaring_);
    approachIfFar();
    if (phase_ == Phase::Approach) return DriveAction::rotate(commandMrad_);
  }
  // Square (or, with no straight wall seen, as set down): now where the walls are across and along.
  phase_ = Phase::Snap;
  return DriveAction::read(Sensor::Front);
#endif
}

#ifndef NXTMAP_NO_START_SQUARING
int Pilot::approachesLeft() const {
  return config_.approachCm > 0 && approached_ < config_.approaches ? config_.approaches - approached_ : 0;
}

void Pilot::approachIfFar() {
  // No straight wall within the sweep's reach: towards an echo (StartSquaring::approachEcho; the sweep ended at its
  // zero, off by the residual), PilotConfig::approachCm.
  // With no echo at all (the middle of a hall): blind, approachMaxCm ahead, then a quarter turn clockwise of the
  // start heading, by turns (a staircase away from the start, towards some wall).
  const StartSquaring::Echo& n = squaring_.approachEcho();
  const bool blind = !n.seen && squaring_.heardNothing();
  const int32_t driveCm = blind ? config_.approachMaxCm : n.cm - config_.approachCm;
  if (squaring_.result().found || approached_ >= config_.approaches || config_.approachCm <= 0 ||
      (!n.seen && !blind) || driveCm < 20)
    return;
  ++approached_;
  phase_ = Phase::Approach;
  approachStep_ = 0;
  approachMm_ = 10 * (driveCm < config_.approachMaxCm ? driveCm : config_.approachMaxCm);
  const int32_t towardsMrad = blind ? (approached_ % 2 == 0 ? WallDirection::kQuarterMrad : 0) : n.mrad;
  commandMrad_ = towardsMrad - squaring_.residualMrad();
  if (!blind) squaring_.avoid(n.mrad);
  correctionMrad_ += static_cast<uint32_t>(commandMrad_ < 0 ? -commandMrad_ : commandMrad_);
}

DriveAction Pilot::snap(const DriveEvent& e) {
  NXTMAP_CHECK(e.kind == DriveEvent::Kind::Range);
  const Dir d = sensorDir(startPose_.heading, e.sensor);
  const int32_t distMm = (static_cast<int32_t>(e.reading.cm) + explorer_.config().geometry.mountCm) * 10;
  const int axis = isVertical(d) ? 1 : 0;
  if (e.reading.status == RangeStatus::Good && e.reading.cm <= config_.snapRangeCm &&
      (snapDistMm_[axis] == 0 || distMm < snapDistMm_[axis])) {
    // The face lies (k - 1/2) cells from the cell's centre (where the pose readings take it to be): the
    // offset along d is that minus the distance, the one of them within half a cell.
    int32_t along = (explorer_.config().geometry.faceMm(1) - distMm) % cellMm_;
    if (along <= -cellMm_ / 2) along += cellMm_;
    if (along > cellMm_ / 2) along -= cellMm_;
    snapDistMm_[axis] = distMm;
    snapMm_[axis] = (isVertical(d) ? dy(d) : dx(d)) * along;
  }
  const int next = static_cast<int>(e.sensor) + 1;
  if (next < kSensorCount) return DriveAction::read(static_cast<Sensor>(next));
  const int64_t sigma = squaring_.result().found    ? config_.squaredHeadingMrad
                        : calibration_.turnedBack() ? kTurnedBackHeadingMrad
                                                    : config_.unsquaredHeadingMrad;
  const int64_t residual = squaring_.residualMrad();  // as set down, when no wall was seen
  snapVarianceMrad2_ = config_.startHeadingVarianceMrad2 + sigma * sigma + residual * residual;
  return DriveAction::think();  // the explorer starts on the Thought (Pilot::stepCorrected)
}
#endif

#ifndef NXTMAP_NO_START_SQUARING
DriveAction Pilot::approach(const DriveEvent& e) {
  const bool rotated = e.kind == DriveEvent::Kind::Rotated, driven = e.kind == DriveEvent::Kind::Driven;
  if (approachStep_ == 0 && rotated) {
    approachTurnMrad_ = e.measured ? e.achieved : commandMrad_;
    approachStep_ = 1;
    return DriveAction::drive(approachMm_);
  }
  if (approachStep_ == 1 && driven) {  // driven all the way or stopped by something: sweep from there
    const int32_t mm = e.measured ? e.achieved : approachMm_;
    approachCells_ += static_cast<uint32_t>((mm < 0 ? -mm : mm) + cellMm_ / 2) / static_cast<uint32_t>(cellMm_);
    approachStep_ = 2;
    commandMrad_ = -approachTurnMrad_;
    correctionMrad_ += static_cast<uint32_t>(commandMrad_ < 0 ? -commandMrad_ : commandMrad_);
    return DriveAction::rotate(commandMrad_);
  }
  NXTMAP_CHECK(approachStep_ == 2 && rotated);  // an event that does not answer the action in progress
  phase_ = Phase::Square;
  // A calibration whose sweep saw no wall measures from here (its first sweep squares, with the approaches left).
  if (config_.calibrateTurns > 0 && !calibration_.found()) return calibration_.begin(approachesLeft());
  return squaring_.begin(approachesLeft());
}
#endif

#ifndef NXTMAP_NO_START_SQUARING
WheelCalibration Pilot::wheels() const {
  WheelCalibration w = tracker_.wheels();
  w.turnPpm += turnErrorPpm_;
  return w;
}
#endif

DriveAction Pilot::step(const DriveEvent& e) {
#ifdef NXTMAP_NO_START_SQUARING
  return stepCorrected(e);
#else
  // The wheels turn by (1 + e) times what they are told, and the encoders count what was told: the
  // pilot thinks in true angles and the wheels are told and heard through the correction, which takes
  // in what the tracker has learnt of e so far.
  turnErrorPpm_ += tracker_.takeTurnPpm();
  if (turnErrorPpm_ == 0) return stepCorrected(e);
  const int64_t scale = 1000000 + turnErrorPpm_;
  DriveEvent heard = e;
  if (e.kind == DriveEvent::Kind::Rotated && e.measured)
    heard.achieved = static_cast<int32_t>(static_cast<int64_t>(e.achieved) * scale / 1000000);
  DriveAction a = stepCorrected(heard);
  if (a.kind == DriveAction::Kind::Rotate)
    a.value = static_cast<int32_t>(static_cast<int64_t>(a.value) * 1000000 / scale);
  return a;
#endif
}

}  // namespace nxtmap
