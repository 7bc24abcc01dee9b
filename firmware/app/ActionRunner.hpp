#pragma once
#include <cstdint>

#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"
#include "common/sensing/RangeFilter.hpp"
#include "firmware/drivers/MotionController.hpp"
#include "firmware/drivers/MotionGeometry.hpp"
#include "firmware/drivers/SonarSequencer.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap::fw {

// Carries out one DriveAction (from the Pilot, or from path following) on the robot without
// blocking, and produces the DriveEvent that answers it. Read: raw samples of the sensor's port
// through the SonarSequencer into a RangeFilter until it is done. Drive (mm): both wheels the
// same counts; if the motion is blocked, the robot drives back to where it started and answers
// driven(blocked). Rotate (mrad, + clockwise): a spin on the spot, left wheel forward for
// clockwise. Think: the core wants more CPU; answered with thought() on the next poll (the next
// main-loop pass), so drivers and motion control run in between. Pure logic: wheel counts and time
// in, wheel power out.
class ActionRunner {
 public:
  struct Wheels {
    int32_t left;
    int32_t right;
  };

  NXTMAP_RUN_ONCE ActionRunner(MotionController& motion, SonarSequencer& sonar, const MotionGeometry& drive,
                               const RangeGeometry& range, const uint8_t (&sensorPorts)[4])
      : motion_(motion), sonar_(sonar), drive_(drive), filter_(range) {
    for (int i = 0; i < 4; ++i) ports_[i] = sensorPorts[i];
  }

  bool busy() const { return phase_ != Phase::Idle; }
  uint32_t failedRotations() const { return failedRotations_; }

  void begin(const DriveAction& a, Wheels now, uint32_t nowMs) {
    action_ = a;
    start_ = now;
    target_ = now;
    switch (a.kind) {
      case DriveAction::Kind::Read:
        filter_.reset();
        phase_ = Phase::Reading;
        break;
      case DriveAction::Kind::Drive: {
        const int32_t c = drive_.countsForMm(a.value);
        target_ = Wheels{now.left + c, now.right + c};
        motion_.start(now.left, now.right, c, c, nowMs);
        phase_ = Phase::Driving;
        break;
      }
      case DriveAction::Kind::Rotate: {
        const int32_t c = drive_.countsForMrad(a.value);
        target_ = Wheels{now.left + c, now.right - c};
        motion_.start(now.left, now.right, c, -c, nowMs);
        phase_ = Phase::Rotating;
        break;
      }
      case DriveAction::Kind::Think: phase_ = Phase::Thinking; break;
      case DriveAction::Kind::Done: phase_ = Phase::Idle; break;
    }
  }

  // Advances the action; true (with `out` set) when it is over.
  bool poll(Wheels now, uint32_t nowMs, DriveEvent& out) {
    switch (phase_) {
      case Phase::Idle: return false;
      case Phase::Reading: return pollRead(nowMs, out);
      case Phase::Thinking: return finish(DriveEvent::thought(), out);
      case Phase::Driving: {
        const MotionController::Status s = motion_.update(now.left, now.right, nowMs);
        if (s == MotionController::Status::Done) {
          // Report what the encoders counted, so the pilot's pose follows the real wheels.
          const int32_t counts = ((now.left - start_.left) + (now.right - start_.right)) / 2;
          return finish(DriveEvent::drivenBy(drive_.mmForCounts(counts)), out);
        }
        if (s == MotionController::Status::Blocked) {
          motion_.start(now.left, now.right, start_.left - now.left, start_.right - now.right, nowMs);
          phase_ = Phase::Backing;
        }
        return false;
      }
      case Phase::Backing: {
        const MotionController::Status s = motion_.update(now.left, now.right, nowMs);
        if (s == MotionController::Status::Done || s == MotionController::Status::Blocked)
          return finish(DriveEvent::driven(true), out);
        return false;
      }
      case Phase::Rotating: {
        const MotionController::Status s = motion_.update(now.left, now.right, nowMs);
        if (s == MotionController::Status::Blocked) ++failedRotations_;
        if (s == MotionController::Status::Done || s == MotionController::Status::Blocked) {
          const int32_t counts = ((now.left - start_.left) - (now.right - start_.right)) / 2;
          return finish(DriveEvent::rotatedBy(drive_.mradForCounts(counts)), out);
        }
        return false;
      }
    }
    return false;
  }

  // Stops whatever runs (motors to 0); no event. resume() can carry the same action on.
  void abort() {
    motion_.stop();
    if (phase_ != Phase::Idle) interrupted_ = phase_;
    phase_ = Phase::Idle;
  }
  // Carries on an aborted action: a drive or rotation to the wheel counts it was aiming at (not
  // its whole distance again), a reading from scratch; a drive that was already returning from
  // an obstacle returns to its start. False when nothing was interrupted.
  bool resume(Wheels now, uint32_t nowMs) {
    const Phase p = interrupted_;
    interrupted_ = Phase::Idle;
    switch (p) {
      case Phase::Idle: return false;
      case Phase::Reading: filter_.reset(); break;
      case Phase::Thinking: break;
      case Phase::Driving:
      case Phase::Rotating:
        motion_.start(now.left, now.right, target_.left - now.left, target_.right - now.right, nowMs);
        break;
      case Phase::Backing:
        motion_.start(now.left, now.right, start_.left - now.left, start_.right - now.right, nowMs);
        break;
    }
    phase_ = p;
    return true;
  }
  int8_t power(int wheel) const { return motion_.power(wheel); }
  // The last sample of sensor port 0..3, cm (255: no echo); false before the port's first sample.
  bool lastReading(uint8_t port, uint8_t& cm) const {
    if (port >= 4 || (seen_ & (1u << port)) == 0) return false;
    cm = last_[port];
    return true;
  }

 private:
  enum class Phase : uint8_t { Idle, Reading, Thinking, Driving, Backing, Rotating };

  bool pollRead(uint32_t nowMs, DriveEvent& out) {
    sonar_.poll(nowMs);
    if (sonar_.ready()) {
      const uint8_t cm = sonar_.take();
      last_[sonar_.port() & 3] = cm;
      seen_ = static_cast<uint8_t>(seen_ | (1u << (sonar_.port() & 3)));
      filter_.add(cm);
    }
    if (filter_.done()) return finish(DriveEvent::range(action_.sensor, filter_.result()), out);
    if (!sonar_.busy()) sonar_.request(ports_[static_cast<int>(action_.sensor)]);
    return false;
  }
  bool finish(const DriveEvent& e, DriveEvent& out) {
    motion_.stop();
    phase_ = Phase::Idle;
    interrupted_ = Phase::Idle;
    out = e;
    return true;
  }

  MotionController& motion_;
  SonarSequencer& sonar_;
  MotionGeometry drive_;
  RangeFilter filter_;
  uint8_t ports_[4] = {0, 1, 2, 3};
  uint8_t last_[4] = {};  // last sample per sensor port, cm
  uint8_t seen_ = 0;      // bit n: port n has a sample
  DriveAction action_{};
  Wheels start_{0, 0};
  Wheels target_{0, 0};
  uint32_t failedRotations_ = 0;
  Phase phase_ = Phase::Idle;
  Phase interrupted_ = Phase::Idle;
};

}  // namespace nxtmap::fw
