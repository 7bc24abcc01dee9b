// A room for sweeps on the spot, for the tests of StartSquaring and TurnCalibration: straight walls read by a sonar
// with a 12 degree cone, whole cm.
#pragma once
#include <cmath>
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap::sweptwalls {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kConeDeg = 12.0;

// One straight wall seen by one sensor: its normal `normalDeg` off the sweep's zero (+ clockwise, in the sensor's
// own frame), `cm` from the sensor along it.
struct Wall {
  double normalDeg;
  double cm;
};

// A sensor facing `facingDeg` reads the wall's distance while the wall's normal lies in its cone, d / cos(off -
// cone) beyond it, whole cm; nothing 60 degrees or more off the normal (the echo glances off) or past 160 cm.
inline int16_t wallReading(const Wall& w, double facingDeg) {
  double off = std::fabs(std::remainder(facingDeg - w.normalDeg, 360.0));
  if (off >= 60.0) return 0;
  off = off > kConeDeg ? off - kConeDeg : 0.0;
  const double cm = w.cm / std::cos(off * kPi / 180.0);
  return cm > 160.0 ? 0 : static_cast<int16_t>(std::lround(cm));
}

// Front sees a wall 25 cm off with its normal at +3 degrees of the sweep; the right sensor one 80 cm off (`rightCm`)
// facing its normal at +9 degrees (the two walls are 6 degrees off square to each other); back and left see nothing.
struct TwoWalls {
  double rightCm = 80.0;
  int16_t read(Sensor s, int32_t headingMrad) const {
    const double deg = headingMrad * 180.0 / (1000.0 * kPi);
    if (s == Sensor::Front) return wallReading(Wall{3.0, 25.0}, deg);
    if (s == Sensor::Right) return wallReading(Wall{9.0, rightCm}, deg);
    return 0;
  }
};

}  // namespace nxtmap::sweptwalls
