#pragma once
#include <cstdint>

#include "common/explore/Pose.hpp"
#include "common/grid/Cell.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap {

// The answer to the previous DriveAction (or the start of a run).
struct DriveEvent {
  enum class Kind : uint8_t { Start, Range, Rotated, Driven, Thought };
  Kind kind = Kind::Start;
  Sensor sensor = Sensor::Front;  // Range
  RangeReading reading;           // Range
  bool blocked = false;           // Driven: the wheels stalled; the drive layer went back to where it started
  Pose pose{};                    // Start: where the robot stands on the explorer's map
  bool measured = false;          // Rotated/Driven: `achieved` holds what the encoders counted
  int32_t achieved = 0;           // Rotated: mrad (+ clockwise); Driven: mm (+ forward)

  static constexpr DriveEvent start() { return DriveEvent{}; }
  // Start (or go on) from a known pose on the explorer's map, at the cell's centre on the axis.
  static DriveEvent startAt(const Pose& p) {
    DriveEvent e;
    e.pose = p;
    return e;
  }
  // The answer to DriveAction::think().
  static DriveEvent thought() {
    DriveEvent e;
    e.kind = Kind::Thought;
    return e;
  }
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
  // The same, with the rotation the wheel encoders measured (mrad, + clockwise).
  static DriveEvent rotatedBy(int32_t mrad) {
    DriveEvent e = rotated();
    e.measured = true;
    e.achieved = mrad;
    return e;
  }
  // The drive asked for was carried out, or not at all when `stalled` (robot back at its start).
  static DriveEvent driven(bool stalled) {
    DriveEvent e;
    e.kind = Kind::Driven;
    e.blocked = stalled;
    return e;
  }
  // A completed drive with the distance the wheel encoders measured (mm, + forward).
  static DriveEvent drivenBy(int32_t mm) {
    DriveEvent e = driven(false);
    e.measured = true;
    e.achieved = mm;
    return e;
  }
};

}  // namespace nxtmap
