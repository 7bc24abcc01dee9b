// The shapes the Scene tests build scenes and bodies from (SceneTest, ScenePropertyTest): boxes of cm, squares
// turned by radians, and pi.
#pragma once

#include <cmath>
#include <vector>

#include "host/sim/Scene.hpp"

namespace nxtmap::sim::test {

inline constexpr double kPi = 3.14159265358979323846;

inline Ring box(double x0, double y0, double x1, double y1, Surface surface = Surface::Hard) {
  return Ring{{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)}, surface};
}

// The body: a square of side 2h centred at c, turned by a radians.
inline std::vector<Vec2> square(const Vec2& c, double h, double a) {
  const Vec2 ax(std::cos(a), std::sin(a)), ay(-std::sin(a), std::cos(a));
  return {c - h * ax - h * ay, c + h * ax - h * ay, c + h * ax + h * ay, c - h * ax + h * ay};
}

}  // namespace nxtmap::sim::test
