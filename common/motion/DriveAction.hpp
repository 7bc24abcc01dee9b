#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// What the pilot asks the wheels and sensors to do: the explorer's cell moves and quarter turns
// turned into metric motion with pose corrections. Never blocks: the caller carries it out and
// answers with a DriveEvent.
struct DriveAction {
  enum class Kind : uint8_t {
    Read,    // one filtered reading of `sensor`; answer DriveEvent::range
    Rotate,  // turn in place by `value` milliradians, + = clockwise; answer DriveEvent::rotated
    Drive,   // drive `value` mm straight, + forward, - backward; answer DriveEvent::driven
    Done,    // mapping is finished
    Think,   // the core needs more CPU before it can decide (nothing moves): answer
             // DriveEvent::thought() when convenient, e.g. on the next pass of the main loop
  };
  Kind kind = Kind::Done;
  Sensor sensor = Sensor::Front;
  int32_t value = 0;  // Rotate: mrad (|value| <= 4 * 1571); Drive: mm

  static constexpr DriveAction read(Sensor s) { return DriveAction{Kind::Read, s, 0}; }
  static constexpr DriveAction rotate(int32_t mrad) { return DriveAction{Kind::Rotate, Sensor::Front, mrad}; }
  static constexpr DriveAction drive(int32_t mm) { return DriveAction{Kind::Drive, Sensor::Front, mm}; }
  static constexpr DriveAction done() { return DriveAction{Kind::Done, Sensor::Front, 0}; }
  static constexpr DriveAction think() { return DriveAction{Kind::Think, Sensor::Front, 0}; }
};

}  // namespace nxtmap
