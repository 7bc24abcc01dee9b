#pragma once
#include <cstdint>

#include "common/explore/Action.hpp"
#include "common/explore/Event.hpp"
#include "common/sensing/RangeFilter.hpp"
#include "firmware/drivers/MotionController.hpp"
#include "firmware/drivers/MotionGeometry.hpp"
#include "firmware/drivers/SonarSequencer.hpp"

namespace nxtmap::fw {

// Carries out one explorer Action on the robot without blocking, and produces the Event that
// answers it. Read: raw samples of the sensor's port through the SonarSequencer into a RangeFilter
// until it is done. Move: the wheels travel the cell's counts; if the motion is blocked, the robot
// drives back to where the move started and answers Blocked. Turn: a spin on the spot (left wheel
// forward for clockwise). Pure logic: wheel counts and time in, wheel power out.
class ActionRunner {
 public:
  struct Wheels {
    int32_t left;
    int32_t right;
  };

  ActionRunner(MotionController& motion, SonarSequencer& sonar, const MotionGeometry& drive,
               const RangeGeometry& range, const uint8_t (&sensorPorts)[4])
      : motion_(motion), sonar_(sonar), drive_(drive), filter_(range) {
    for (int i = 0; i < 4; ++i) ports_[i] = sensorPorts[i];
  }

  bool busy() const { return phase_ != Phase::Idle; }
  uint32_t failedTurns() const { return failedTurns_; }

  void begin(const Action& a, Wheels now, uint32_t nowMs) {
    action_ = a;
    start_ = now;
    switch (a.kind) {
      case Action::Kind::Read:
        filter_.reset();
        phase_ = Phase::Reading;
        break;
      case Action::Kind::Move: {
        const int32_t c = drive_.countsForCells(a.amount);
        motion_.start(now.left, now.right, c, c, nowMs);
        phase_ = Phase::Moving;
        break;
      }
      case Action::Kind::Turn: {
        const int32_t c = drive_.countsForTurn(a.amount);
        motion_.start(now.left, now.right, c, -c, nowMs);
        phase_ = Phase::Turning;
        break;
      }
      case Action::Kind::Done:
        phase_ = Phase::Idle;
        break;
    }
  }

  // Advances the action; true (with `out` set) when it is over.
  bool poll(Wheels now, uint32_t nowMs, Event& out) {
    switch (phase_) {
      case Phase::Idle:
        return false;
      case Phase::Reading:
        return pollRead(nowMs, out);
      case Phase::Moving: {
        const MotionController::Status s = motion_.update(now.left, now.right, nowMs);
        if (s == MotionController::Status::Done) return finish(Event::moved(action_.amount), out);
        if (s == MotionController::Status::Blocked) {
          motion_.start(now.left, now.right, start_.left - now.left, start_.right - now.right, nowMs);
          phase_ = Phase::Backing;
        }
        return false;
      }
      case Phase::Backing: {
        const MotionController::Status s = motion_.update(now.left, now.right, nowMs);
        if (s == MotionController::Status::Done || s == MotionController::Status::Blocked)
          return finish(Event::blocked(), out);
        return false;
      }
      case Phase::Turning: {
        const MotionController::Status s = motion_.update(now.left, now.right, nowMs);
        if (s == MotionController::Status::Blocked) ++failedTurns_;
        if (s == MotionController::Status::Done || s == MotionController::Status::Blocked)
          return finish(Event::turned(action_.amount), out);
        return false;
      }
    }
    return false;
  }

  // Stops whatever runs (motors to 0); no event.
  void abort() {
    motion_.stop();
    phase_ = Phase::Idle;
  }
  int8_t power(int wheel) const { return motion_.power(wheel); }

 private:
  enum class Phase : uint8_t { Idle, Reading, Moving, Backing, Turning };

  bool pollRead(uint32_t nowMs, Event& out) {
    sonar_.poll(nowMs);
    if (sonar_.ready()) filter_.add(sonar_.take());
    if (filter_.done()) return finish(Event::range(action_.sensor, filter_.result()), out);
    if (!sonar_.busy()) sonar_.request(ports_[static_cast<int>(action_.sensor)]);
    return false;
  }
  bool finish(const Event& e, Event& out) {
    motion_.stop();
    phase_ = Phase::Idle;
    out = e;
    return true;
  }

  MotionController& motion_;
  SonarSequencer& sonar_;
  MotionGeometry drive_;
  RangeFilter filter_;
  uint8_t ports_[4] = {0, 1, 2, 3};
  Action action_{};
  Wheels start_{0, 0};
  uint32_t failedTurns_ = 0;
  Phase phase_ = Phase::Idle;
};

}  // namespace nxtmap::fw
