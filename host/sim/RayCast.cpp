#include "host/sim/RayCast.hpp"

#include <cmath>
#include <limits>

namespace nxtmap::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

void directionVector(double deg, double& dx, double& dy) {
  const double quarter = deg / 90.0;
  if (quarter == std::floor(quarter) && std::fabs(quarter) < 1e9) {
    static constexpr double kDx[4] = {0.0, 1.0, 0.0, -1.0};
    static constexpr double kDy[4] = {-1.0, 0.0, 1.0, 0.0};
    const int k = ((static_cast<int>(quarter) % 4) + 4) % 4;
    dx = kDx[k];
    dy = kDy[k];
    return;
  }
  const double rad = deg * kPi / 180.0;
  dx = std::sin(rad);
  dy = -std::cos(rad);
}

RayHit castRay(const World& world, double cellCm, double xCm, double yCm, double deg, double maxCm) {
  double dx = 0.0;
  double dy = 0.0;
  directionVector(deg, dx, dy);
  int col = static_cast<int>(std::floor(xCm / cellCm));
  int row = static_cast<int>(std::floor(yCm / cellCm));
  if (world.blocked(col, row)) return RayHit{true, 0.0, 0.0};

  const int stepX = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int stepY = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  // Ray parameter t (= distance, the direction is a unit vector) at the next vertical / horizontal cell face.
  double tMaxX = stepX > 0 ? ((col + 1) * cellCm - xCm) / dx : (stepX < 0 ? (col * cellCm - xCm) / dx : kInf);
  double tMaxY = stepY > 0 ? ((row + 1) * cellCm - yCm) / dy : (stepY < 0 ? (row * cellCm - yCm) / dy : kInf);
  const double tDeltaX = stepX != 0 ? cellCm / std::fabs(dx) : kInf;
  const double tDeltaY = stepY != 0 ? cellCm / std::fabs(dy) : kInf;

  while (true) {
    double t = 0.0;
    bool verticalFace = false;
    if (tMaxX < tMaxY) {
      t = tMaxX;
      col += stepX;
      tMaxX += tDeltaX;
      verticalFace = true;
    } else {
      t = tMaxY;
      row += stepY;
      tMaxY += tDeltaY;
    }
    if (!(t <= maxCm)) return RayHit{};
    if (world.blocked(col, row)) {
      // A vertical face has normal (+-1, 0): cos(incidence) = |dx|; a horizontal one: |dy|.
      const double cosInc = std::fmin(1.0, verticalFace ? std::fabs(dx) : std::fabs(dy));
      return RayHit{true, t, std::acos(cosInc) * 180.0 / kPi};
    }
  }
}

}  // namespace nxtmap::sim
