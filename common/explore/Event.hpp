#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap {

// What happened: the answer to the previous Action (or the start of a run).
struct Event {
  enum class Kind : uint8_t { Start, Range, Moved, Blocked, Turned };
  Kind kind = Kind::Start;
  Sensor sensor = Sensor::Front;  // Range
  RangeReading reading;           // Range
  int8_t amount = 0;              // Moved: cells (+ forward); Turned: eighths (+ clockwise)

  static constexpr Event start() { return Event{}; }
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
  static Event turned(int8_t eighths) {
    Event e;
    e.kind = Kind::Turned;
    e.amount = eighths;
    return e;
  }
};

}  // namespace nxtmap
