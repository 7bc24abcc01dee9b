#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap {

// The answer to the previous DriveAction (or the start of a run).
struct DriveEvent {
  enum class Kind : uint8_t { Start, Range, Rotated, Driven };
  Kind kind = Kind::Start;
  Sensor sensor = Sensor::Front;  // Range
  RangeReading reading;           // Range
  bool blocked = false;           // Driven: the wheels stalled; the drive layer went back to where it started

  static constexpr DriveEvent start() { return DriveEvent{}; }
  static DriveEvent range(Sensor s, const RangeReading& r) {
    DriveEvent e;
    e.kind = Kind::Range;
    e.sensor = s;
    e.reading = r;
    return e;
  }
  // The rotation asked for was carried out (as well as the wheels could).
  static DriveEvent rotated() {
    DriveEvent e;
    e.kind = Kind::Rotated;
    return e;
  }
  // The drive asked for was carried out, or not at all when `stalled` (robot back at its start).
  static DriveEvent driven(bool stalled) {
    DriveEvent e;
    e.kind = Kind::Driven;
    e.blocked = stalled;
    return e;
  }
};

}  // namespace nxtmap
