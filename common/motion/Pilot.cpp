#include "common/motion/Pilot.hpp"

#include "common/check/Check.hpp"
#include "common/math/IntAbs.hpp"
#include "common/math/IntSqrt.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap {
namespace {
constexpr int32_t clamp32(int32_t v, int32_t lim) { return v < -lim ? -lim : (v > lim ? lim : v); }
// Cells out to which a wall is read for the pose: the mapping range's, or farther (PilotConfig::poseRangeCm).
int16_t poseCellsFor(const RangeGeometry& g, int16_t poseRangeCm) {
  if (poseRangeCm <= g.maxCm) return g.hitCells();
  RangeGeometry far = g;
  far.maxCm = poseRangeCm;
  return far.hitCells();
}
// The tracker learns the turn error beyond the one the pilot already corrects every rotation by.
WheelCalibration trackerWheels(WheelCalibration w) {
  w.turnPpm = 0;
  return w;
}
// The calibration the run makes: the one asked for, or (PilotConfig::calibrateUnknownTurns) one unasked by a robot
// that sweeps and knows its turns no better than an uncalibrated one.
PilotConfig withCalibration(PilotConfig c) {
#ifndef NXTMAP_NO_START_SQUARING
  if (c.calibrateTurns == 0 && c.squareSweepMrad > 0 && c.wheels.turnsUnknown())
    c.calibrateTurns = c.calibrateUnknownTurns;
#endif
  return c;
}
// The tracker's gate, at least PilotConfig::gateCellTenths of a cell.
PoseNoise trackerNoise(PoseNoise n, int32_t cellMm, int32_t tenths) {
  const int32_t floorMm = tenths * cellMm / 10;
  if (n.gateMm < floorMm) n.gateMm = floorMm;
  return n;
}
}  // namespace

NXTMAP_RUN_ONCE Pilot::Pilot(Explorer& explorer, const PilotConfig& config)
    : explorer_(explorer),
      config_(withCalibration(config)),
      tracker_(trackerNoise(config.noise, static_cast<int32_t>(explorer.config().geometry.cellCm) * 10,
                            config.gateCellTenths),
               trackerWheels(config.wheels)),
#ifndef NXTMAP_NO_START_SQUARING
      squaring_(config.squareSweepMrad, config.squareStepMrad, static_cast<int16_t>(config.approachCm + 20),
                config.sonarConeMrad),
      calibration_(squaring_, config_.calibrateTurns),
      turnErrorPpm_(config.wheels.turnPpm),
#endif
      cellMm_(static_cast<int32_t>(explorer.config().geometry.cellCm) * 10),
      poseCells_(poseCellsFor(explorer.config().geometry, config.poseRangeCm)) {
}

Counters Pilot::counters() const {
  Counters c = explorer_.counters();
  c.sensorRequests += poseReads_;
  c.rawSamples += poseSamples_;
  c.correctionMrad += correctionMrad_;
#ifndef NXTMAP_NO_START_SQUARING
  c.sensorRequests += sweepReads_;
  c.rawSamples += sweepSamples_;
  c.correctionMrad += sweepMrad_;
  if (phase_ == Phase::Square) {  // the sweep in progress
    const bool calibrating = config_.calibrateTurns > 0 && !calibration_.finished();
    c.sensorRequests += calibrating ? calibration_.readings() : squaring_.readings();
    c.rawSamples += calibrating ? calibration_.samples() : squaring_.samples();
    c.correctionMrad += calibrating ? calibration_.turnedMrad() : squaring_.turnedMrad();
  }
  c.cellsMoved += approachCells_;
#endif
  return c;
}

int64_t Pilot::handOverHeadingVariance() const {
  // The levelling rotation is a small one: its error has the floor of a quarter of a quarter turn's.
  const int64_t small = config_.noise.turnMradPerQuarter / 4;
  return tracker_.thetaVariance() + small * small;
}

DriveAction Pilot::levelling() const {
  if (!config_.correct || abs32(tracker_.thetaMrad()) < config_.minRotateMrad) return DriveAction::done();
  return DriveAction::rotate(-tracker_.thetaMrad());
}

DriveAction Pilot::begin(const Action& a) {
  pending_ = a;
  switch (a.kind) {
    case Action::Kind::Read:
      // The explorer marks a reading along the axis: take the known heading error out first.
      if (config_.correct && !levelHeld() && abs32(tracker_.thetaMrad()) >= config_.minRotateMrad) {
        phase_ = Phase::Level;
        commandMrad_ = -tracker_.thetaMrad();
        correctionMrad_ += static_cast<uint32_t>(abs32(commandMrad_));
        return DriveAction::rotate(commandMrad_);
      }
      phase_ = Phase::ExplorerRead;
      return DriveAction::read(a.sensor);
    case Action::Kind::Turn: {
      NXTMAP_CHECK(a.amount % 2 == 0);  // explorers keep to the axis grid
      phase_ = Phase::Turn;
      // Whole quarter turns, rounded so that their sum never drifts from a multiple of pi/2.
      turnedUrad_ += static_cast<int64_t>(a.amount / 2) * 1570796;
      commandMrad_ =
          static_cast<int32_t>((turnedUrad_ - commandedUrad_ + (turnedUrad_ >= commandedUrad_ ? 500 : -500)) / 1000);
      commandedUrad_ += static_cast<int64_t>(commandMrad_) * 1000;
#ifndef NXTMAP_NO_START_SQUARING
      quarterMrad_ = static_cast<int16_t>(commandMrad_);
#endif
      // Take out the estimated heading error as well (not part of the quarter-turn bookkeeping).
      if (config_.correct) commandMrad_ -= tracker_.thetaMrad();
      return DriveAction::rotate(commandMrad_);
    }
    case Action::Kind::Move: return beginMove();
    case Action::Kind::Think: phase_ = Phase::Think; return DriveAction::think();
    case Action::Kind::Done: break;
  }
  phase_ = Phase::Done;
  return DriveAction::done();
}

DriveAction Pilot::turnMade(int32_t mrad) {
#ifndef NXTMAP_NO_START_SQUARING
  levelHeld_ = false;
#endif
  tracker_.rotated(mrad, pending_.amount / 2);
  if (pending_.amount != 0) startRun();  // the heading changed: the side walls are others
  return begin(explorer_.step(Event::turned(pending_.amount)));
}

DriveAction Pilot::beginMove() {
  if (!config_.correct) {
    phase_ = Phase::Drive;
    driveMm_ = pending_.amount * cellMm_;
    return DriveAction::drive(driveMm_);
  }
#ifndef NXTMAP_NO_START_SQUARING
  steeredMrad_ = 0;
#endif
  Sensor s;
  if (poseReadWanted(s) || sideReadWanted(s)) {
    phase_ = Phase::PoseRead;
    return DriveAction::read(s);
  }
  // Aim at the centre of the target cell: T = n * cell * f - offset, in (forward, right) parts.
  const Dir heading = explorer_.pose().heading;
  const int32_t tf = pending_.amount * cellMm_ - tracker_.along(heading);
  const int32_t tr = -tracker_.along(rotate(heading, 1));
  if (tf * pending_.amount <= 0) return driveToCentre();  // the target is behind: nothing to aim at
  const bool offLine = abs32(tr) > config_.steerAboveMm;
  const int32_t want =
      offLine ? clamp32(static_cast<int32_t>(static_cast<int64_t>(tr) * 1000 / tf), config_.maxSteerMrad) : 0;
  // Aimed so that the drift's curve (learnt, PoseTracker) ends the drive on the line, not beside it.
  const int32_t turn = want - tracker_.thetaMrad() - tracker_.driftMrad(tf) / 2;
  if (abs32(turn) >= config_.minRotateMrad) {
    phase_ = Phase::Steer;
    commandMrad_ = turn;
    correctionMrad_ += static_cast<uint32_t>(abs32(turn));
    return DriveAction::rotate(turn);
  }
  return driveToCentre();
}

DriveAction Pilot::driveToCentre() {
  const Dir heading = explorer_.pose().heading;
  const int64_t tf = pending_.amount * cellMm_ - tracker_.along(heading);
  const int64_t tr = -tracker_.along(rotate(heading, 1));
  // The target's projection on the line the robot drives along (second order in the heading
  // error t): tf cos t + tr sin t. Steered straight at the target it is the distance to it; when
  // the steering was limited it stops abreast of the target instead of overshooting it, and a
  // target behind is not driven away from.
  const int64_t t = tracker_.thetaMrad();
  int64_t along = tf + tr * t / 1000 - tf * t * t / 2000000;
  if (along * pending_.amount < 0) along = 0;
  const int64_t length = static_cast<int64_t>(isqrt(static_cast<uint64_t>(tf * tf + tr * tr)));
  if (along > length) along = length;
  if (along < -length) along = -length;
  phase_ = Phase::Drive;
  driveMm_ = static_cast<int32_t>(along);
  return DriveAction::drive(driveMm_);
}

DriveAction Pilot::stepCorrected(const DriveEvent& e) {
  switch (e.kind) {
    case DriveEvent::Kind::Start: startPose_ = e.pose;
#ifndef NXTMAP_NO_START_SQUARING
      if (config_.squareSweepMrad > 0) {
        phase_ = Phase::Square;
        return config_.calibrateTurns > 0 ? calibration_.begin(approachesLeft()) : squaring_.begin(approachesLeft());
      }
#endif
      return startExplorer(config_.startHeadingVarianceMrad2);
    case DriveEvent::Kind::Range:
      if (phase_ == Phase::Square) return square(e);
#ifndef NXTMAP_NO_START_SQUARING
      if (phase_ == Phase::Snap) return snap(e);
#endif
      observe(e.sensor, e.reading);
      if (phase_ == Phase::PoseRead) {
        ++poseReads_;
        poseSamples_ += e.reading.samples;
        return beginMove();
      }
      if (phase_ == Phase::ExplorerRead)
        return begin(explorer_.step(Event::range(e.sensor, centred(e.sensor, e.reading))));
      break;
    case DriveEvent::Kind::Rotated:
      if (phase_ == Phase::Square) return square(e);
#ifndef NXTMAP_NO_START_SQUARING
      if (phase_ == Phase::Approach) return approach(e);
#endif
      if (phase_ == Phase::Level) {
        tracker_.rotated(e.measured ? e.achieved : commandMrad_, 0);
#ifndef NXTMAP_NO_START_SQUARING
        if (e.measured && abs32(commandMrad_ - e.achieved) >= config_.minRotateMrad) levelHeld_ = true;
#endif
        phase_ = Phase::ExplorerRead;
        return DriveAction::read(pending_.sensor);
      }
      if (phase_ == Phase::Steer || phase_ == Phase::Unsteer) {
#ifndef NXTMAP_NO_START_SQUARING
        steeredMrad_ = static_cast<int16_t>(phase_ == Phase::Steer ? (e.measured ? e.achieved : commandMrad_) : 0);
#endif
        tracker_.rotated(e.measured ? e.achieved : commandMrad_, 0);
        return driveToCentre();
      }
      if (phase_ == Phase::Turn) {
#ifndef NXTMAP_NO_START_SQUARING
        if (e.measured && abs32(commandMrad_ - e.achieved) > config_.turnStallMrad) return turnStalled(e);
#endif
        return turnMade(e.measured ? e.achieved : commandMrad_);
      }
#ifndef NXTMAP_NO_START_SQUARING
      if (phase_ == Phase::TurnBack) return turnedBack(e);
      if (phase_ == Phase::ThreePoint) return threePoint(e);
#endif
      break;
    case DriveEvent::Kind::Thought:
      if (phase_ == Phase::Think) return begin(explorer_.step(Event::thought()));
#ifndef NXTMAP_NO_START_SQUARING
      if (phase_ == Phase::Snap) return startExplorer(snapVarianceMrad2_);
#endif
      break;
    case DriveEvent::Kind::Driven:
#ifndef NXTMAP_NO_START_SQUARING
      if (phase_ == Phase::Approach) return approach(e);
      if (phase_ == Phase::ThreePoint) return threePoint(e);
#endif
      if (phase_ != Phase::Drive) break;
#ifndef NXTMAP_NO_START_SQUARING
      if (e.blocked && steeredMrad_ != 0) {  // back where it started (DriveEvent::blocked): try it unsteered
        phase_ = Phase::Unsteer;
        commandMrad_ = -steeredMrad_;
        return DriveAction::rotate(commandMrad_);
      }
#endif
      if (e.blocked) return begin(explorer_.step(Event::blocked()));
      {
        const Dir heading = explorer_.pose().heading;
        const int32_t mm = e.measured ? e.achieved : driveMm_;
        sides_.drove(heading, mm, tracker_.thetaMrad());
        tracker_.drove(mm, heading);
        tracker_.rebase(heading, pending_.amount, cellMm_);
        readHere_ = 0;
#ifndef NXTMAP_NO_START_SQUARING
        levelHeld_ = false;
#endif
      }
      return begin(explorer_.step(Event::moved(pending_.amount)));
  }
  // An event that does not answer the action in progress: a caller's mistake.
  NXTMAP_CHECK(phase_ == Phase::Done);
  return DriveAction::done();
}

}  // namespace nxtmap
