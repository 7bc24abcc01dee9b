#pragma once
#include <cstdint>

#include "common/explore/Pose.hpp"
#include "common/grid/Cell.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap {

// What happened: the answer to the previous Action (or the start of a run).
struct Event {
  enum class Kind : uint8_t { Start, Range, Moved, Blocked, Turned, Thought };
  Kind kind = Kind::Start;
  Sensor sensor = Sensor::Front;  // Range
  RangeReading reading;           // Range
  int8_t amount = 0;              // Moved: cells (+ forward); Turned: eighths (+ clockwise); Blocked: 1 a turn
  Pose pose{};                    // Start: where the robot stands on the explorer's map

  static constexpr Event start() { return Event{}; }
  // Start (or go on) from a known pose on the map the explorer was given (e.g. after the robot
  // followed a path or the map came from the PC).
  static Event startAt(const Pose& p) {
    Event e;
    e.pose = p;
    return e;
  }
  // The answer to Action::think().
  static Event thought() {
    Event e;
    e.kind = Kind::Thought;
    return e;
  }
  static Event range(Sensor s, const RangeReading& r) {
    Event e;
    e.kind = Kind::Range;
    e.sensor = s;
    e.reading = r;
    return e;
  }
  static Event moved(int8_t cells) {
    Event e;
    e.kind = Kind::Moved;
    e.amount = cells;
    return e;
  }
  static Event blocked() {
    Event e;
    e.kind = Kind::Blocked;
    return e;
  }
  // The turn towards the next move stalled (the body met something turning on the spot) and was turned
  // back: the way is blocked there, but the cell ahead is only suspect (amount 1), not known occupied.
  static Event turnBlocked() {
    Event e = blocked();
    e.amount = 1;
    return e;
  }
  static Event turned(int8_t eighths) {
    Event e;
    e.kind = Kind::Turned;
    e.amount = eighths;
    return e;
  }
};

}  // namespace nxtmap
