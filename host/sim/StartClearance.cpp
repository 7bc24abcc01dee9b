#include "host/sim/StartClearance.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nxtmap::sim {
namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int kDiscSides = 32;
constexpr double kEdgeCm = 0.01;  // the disc as a polygon drawn round it (never smaller than the disc)

std::vector<Vec2> discAround(const Vec2& p, double radiusCm) {
  const double outer = radiusCm / std::cos(kPi / kDiscSides);
  std::vector<Vec2> poly;
  poly.reserve(kDiscSides);
  for (int i = 0; i < kDiscSides; ++i) {
    const double a = 2.0 * kPi * i / kDiscSides;
    poly.emplace_back(p.x() + outer * std::cos(a), p.y() + outer * std::sin(a));
  }
  return poly;
}

// The square of side cellCm centred `ahead` cells forward and `right` cells right of the pose's centre.
std::vector<Vec2> cellBeside(const StartPose& pose, double cellCm, int ahead, int right) {
  const double rad = pose.headingDeg * kPi / 180.0;
  const Vec2 forward(std::sin(rad), -std::cos(rad)), side(std::cos(rad), std::sin(rad));
  const Vec2 centre = pose.cm + cellCm * (ahead * forward + right * side);
  const double h = cellCm / 2.0 - kEdgeCm;  // its open interior: a wall along its edge is beside it
  return {centre + h * (forward + side), centre + h * (forward - side), centre - h * (forward + side),
          centre - h * (forward - side)};
}

// Nothing solid on the straight way from a to b (a person carries the robot no farther than that).
bool inSight(const Scene& scene, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length = std::hypot(d.x(), d.y());
  if (length <= 0.0) return true;
  const double deg = std::atan2(d.x(), -d.y()) * 180.0 / kPi;  // compass: 0 = -y (north), 90 = +x
  return !scene.cast(a, deg, length).hit;
}

// The offsets (i, j) of whole cells within kReachCells of the start that its centre reaches by steps of a cell
// along the plane's axes, each in sight of the last (round an obstacle, never through a wall): index
// (j + kReachCells) * side + i + kReachCells.
std::vector<bool> reachableAround(const Scene& scene, const Vec2& start, double cellCm) {
  constexpr int kSide = 2 * kReachCells + 1;
  std::vector<bool> seen(kSide * kSide, false);
  std::vector<int> queue{kReachCells * kSide + kReachCells};
  seen[queue[0]] = true;
  const double x0 = start.x(), y0 = start.y();
  const auto at = [x0, y0, cellCm](int index) {
    return Vec2(x0 + (index % kSide - kReachCells) * cellCm, y0 + (index / kSide - kReachCells) * cellCm);
  };
  for (size_t q = 0; q < queue.size(); ++q) {
    const int from = queue[q], x = from % kSide, y = from / kSide;
    const int steps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (const auto& s : steps) {
      const int nx = x + s[0], ny = y + s[1], to = ny * kSide + nx;
      if (nx < 0 || ny < 0 || nx >= kSide || ny >= kSide || seen[to]) continue;
      if (scene.solidAt(at(to)) || !inSight(scene, at(from), at(to))) continue;
      seen[to] = true;
      queue.push_back(to);
    }
  }
  return seen;
}
}  // namespace

bool roomToTurnAt(const Scene& scene, const StartPose& pose, double cellCm, double sweepCm) {
  if (scene.solidAt(pose.cm) || scene.touches(discAround(pose.cm, sweepCm))) return false;
  return !scene.touches(cellBeside(pose, cellCm, 1, 0)) && !scene.touches(cellBeside(pose, cellCm, -1, 0)) &&
         !scene.touches(cellBeside(pose, cellCm, 0, 1)) && !scene.touches(cellBeside(pose, cellCm, 0, -1));
}

ClearStart withRoomToTurn(const Scene& scene, const StartPose& start, double cellCm, double sweepCm) {
  if (roomToTurnAt(scene, start, cellCm, sweepCm)) return ClearStart{start, 0.0};
  struct Offset {
    int i, j;
    double cm;
  };
  std::vector<Offset> offsets;
  for (int j = -kReachCells; j <= kReachCells; ++j)
    for (int i = -kReachCells; i <= kReachCells; ++i)
      if (i != 0 || j != 0) offsets.push_back(Offset{i, j, cellCm * std::hypot(i, j)});
  std::stable_sort(offsets.begin(), offsets.end(), [](const Offset& a, const Offset& b) { return a.cm < b.cm; });
  const std::vector<bool> reachable = reachableAround(scene, start.cm, cellCm);
  for (const Offset& o : offsets) {
    const StartPose p{start.cm + Vec2(o.i * cellCm, o.j * cellCm), start.headingDeg};
    const bool reached = reachable[(o.j + kReachCells) * (2 * kReachCells + 1) + o.i + kReachCells];
    if (roomToTurnAt(scene, p, cellCm, sweepCm) && (inSight(scene, start.cm, p.cm) || reached))
      return ClearStart{p, o.cm};
  }
  return ClearStart{start, -1.0};
}

}  // namespace nxtmap::sim
