#include "host/sim/SceneAxes.hpp"

#include <cmath>

namespace nxtmap::sim {

double sceneAxesDeg(const Scene& scene) {
  double s = 0.0, c = 0.0;
  for (const Edge& e : scene.edges()) {
    const Vec2 d = e.b - e.a;
    const double length = d.norm();
    // Compass angle of the edge (0 = -y, clockwise: the plane's y axis points south), four times over.
    const double quad = 4.0 * std::atan2(d.x(), -d.y());
    s += length * std::sin(quad);
    c += length * std::cos(quad);
  }
  if (s == 0.0 && c == 0.0) return 0.0;
  double deg = std::atan2(s, c) / 4.0 * 180.0 / 3.14159265358979323846;
  if (deg <= -45.0) deg += 90.0;
  return deg;
}

}  // namespace nxtmap::sim
