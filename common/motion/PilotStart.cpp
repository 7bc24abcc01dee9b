// The pilot's start (sweep to the walls, turn calibration) and the turn correction around every step.
#include "common/check/Check.hpp"
#include "common/motion/Pilot.hpp"

namespace nxtmap {

DriveAction Pilot::startExplorer(int64_t headingVarianceMrad2) {
  tracker_.reset(headingVarianceMrad2);
  readHere_ = 0;
  startRun();
  return begin(explorer_.step(Event::startAt(startPose_)));
}

DriveAction Pilot::square(const DriveEvent& e) {
#ifdef NXTMAP_NO_START_SQUARING
  (void)e;
  NXTMAP_CHECK(false);  // never in Phase::Square without the sweep
  return DriveAction::done();
#else
  if (config_.calibrateTurns > 0) {
    const DriveAction a = calibration_.step(e);
    if (!calibration_.finished()) return a;
    if (calibration_.found()) turnErrorPpm_ += calibration_.errorPpm();
  } else {
    const DriveAction a = squaring_.step(e);
    if (!squaring_.finished()) return a;
  }
  // Square (or as set down, with no wall seen): the tracker starts with what is left of the heading error.
  const int64_t sigma = squaring_.result().found ? config_.squaredHeadingMrad : 0;
  const int64_t residual = squaring_.residualMrad();
  return startExplorer(config_.startHeadingVarianceMrad2 + sigma * sigma + residual * residual);
#endif
}

DriveAction Pilot::step(const DriveEvent& e) {
#ifdef NXTMAP_NO_START_SQUARING
  return stepCorrected(e);
#else
  // The wheels turn by (1 + e) times what they are told, and the encoders count what was told: the
  // pilot thinks in true angles and the wheels are told and heard through the correction.
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
