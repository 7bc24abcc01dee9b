#pragma once
#include <cstdint>

namespace nxtmap::fw {

// Closed-loop motion of the two drive wheels to target encoder counts, updated every millisecond.
// Both wheels travel the same number of counts (straight: same sign; spin turn: opposite signs).
// Per wheel: power proportional to the counts left, clamped to [minPower, maxPower], plus a
// synchronisation term that slows the wheel ahead of the other. Done when both wheels stayed on their
// targets (reached, at most `tolerance` counts beyond) for settleMs; Blocked when the wheels made no
// progress for stallMs while driven, or the move took longer than timeoutMs. Pure logic: counts in,
// power out.
class MotionController {
 public:
  enum class Status : uint8_t { Idle, Running, Done, Blocked };
  struct Tuning {
    int16_t maxPower = 70;  // % of battery
    int16_t minPower = 22;  // below this the NXT motor does not turn under load
    int16_t gainPer16 = 8;  // power per count left, in 1/16
    int16_t syncPer4 = 6;   // power per count of lead over the other wheel, in 1/4
    int16_t tolerance = 1;  // counts a wheel may end beyond its target; it stops on reaching it (one count of
                            // spin = 0.5 degree at 112 mm track: stopping a count short left every turn short
                            // and a correction of one count undone)
    uint16_t settleMs = 40;
    uint16_t stallMs = 500;
    uint16_t timeoutMs = 8000;
  };

  MotionController() = default;
  explicit MotionController(const Tuning& t) : t_(t) {}

  // Starts a move by (deltaLeft, deltaRight) counts from the current counts, |deltaLeft| == |deltaRight|.
  void start(int32_t left, int32_t right, int32_t deltaLeft, int32_t deltaRight, uint32_t nowMs) {
    start_[0] = left;
    start_[1] = right;
    target_[0] = left + deltaLeft;
    target_[1] = right + deltaRight;
    sign_[0] = deltaLeft >= 0 ? 1 : -1;
    sign_[1] = deltaRight >= 0 ? 1 : -1;
    last_[0] = left;
    last_[1] = right;
    startMs_ = lastProgressMs_ = nowMs;
    settledSince_ = 0;
    settled_ = false;
    power_[0] = power_[1] = 0;
    status_ = Status::Running;
  }

  // Stops driving (power 0); the status becomes Idle.
  void stop() {
    power_[0] = power_[1] = 0;
    status_ = Status::Idle;
  }

  // One control step with the current counts. Returns the status; power() holds the output.
  Status update(int32_t left, int32_t right, uint32_t nowMs) {
    if (status_ != Status::Running) {
      power_[0] = power_[1] = 0;
      return status_;
    }
    const int32_t now[2] = {left, right};
    if (now[0] != last_[0] || now[1] != last_[1]) lastProgressMs_ = nowMs;
    last_[0] = now[0];
    last_[1] = now[1];

    // Lead of the left wheel over the right along their own directions of travel.
    const int32_t lead = (now[0] - start_[0]) * sign_[0] - (now[1] - start_[1]) * sign_[1];
    bool within = true;
    for (int w = 0; w < 2; ++w) {
      const int32_t rest = target_[w] - now[w];
      const int32_t mag = rest < 0 ? -rest : rest;
      const int32_t past = -rest * sign_[w];  // counts beyond the target along the move's direction
      if (past >= 0 && past <= t_.tolerance) {
        power_[w] = 0;
        continue;
      }
      within = false;
      int32_t p = (mag * t_.gainPer16) / 16;
      if (p < t_.minPower) p = t_.minPower;
      if (p > t_.maxPower) p = t_.maxPower;
      // Slow the wheel that is ahead (only while both still travel forward along their paths).
      const int32_t ahead = (w == 0 ? lead : -lead);
      if (ahead > 0 && rest * sign_[w] > 0) p -= (ahead * t_.syncPer4) / 4;
      if (p < 0) p = 0;
      power_[w] = static_cast<int8_t>(rest > 0 ? p : -p);
    }
    if (within) {
      if (!settled_) {
        settled_ = true;
        settledSince_ = nowMs;
      }
      if (nowMs - settledSince_ >= t_.settleMs) {
        power_[0] = power_[1] = 0;
        status_ = Status::Done;
      }
      return status_;
    }
    settled_ = false;
    if (nowMs - lastProgressMs_ >= t_.stallMs || nowMs - startMs_ >= t_.timeoutMs) {
      power_[0] = power_[1] = 0;
      status_ = Status::Blocked;
    }
    return status_;
  }

  Status status() const { return status_; }
  int8_t power(int wheel) const { return power_[wheel]; }
  // Counts travelled so far along the move's direction, per wheel.
  int32_t travelled(int wheel) const { return (last_[wheel] - start_[wheel]) * sign_[wheel]; }

 private:
  Tuning t_{};
  int32_t start_[2] = {0, 0}, target_[2] = {0, 0}, last_[2] = {0, 0};
  int8_t sign_[2] = {1, 1};
  int8_t power_[2] = {0, 0};
  uint32_t startMs_ = 0, lastProgressMs_ = 0, settledSince_ = 0;
  bool settled_ = false;
  Status status_ = Status::Idle;
};

}  // namespace nxtmap::fw
