#include "host/sim/PolygonCheck.hpp"

#include <algorithm>
#include <cmath>

namespace nxtmap::sim::polygon {

namespace {

double cross(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

// Distance from p to segment ab.
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Signed distance of p from the line through ab: > 0 left of a->b (y up), < 0 right.
double sideOf(const Vec2& a, const Vec2& b, const Vec2& p) {
  const double len = (b - a).norm();
  return len > 0.0 ? cross(b - a, p - a) / len : (p - a).norm();
}

// -1, 0 or +1: which side of line ab p lies on, 0 within the tolerance.
int sign(const Vec2& a, const Vec2& b, const Vec2& p) {
  const double s = sideOf(a, b, p);
  return s > kTouchTolerance ? 1 : (s < -kTouchTolerance ? -1 : 0);
}

bool boxesApart(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double t = kTouchTolerance;
  return std::max(a.x(), b.x()) + t < std::min(c.x(), d.x()) || std::max(c.x(), d.x()) + t < std::min(a.x(), b.x()) ||
         std::max(a.y(), b.y()) + t < std::min(c.y(), d.y()) || std::max(c.y(), d.y()) + t < std::min(a.y(), b.y());
}

}  // namespace

std::vector<size_t> distinctPoints(const std::vector<Vec2>& points, bool ring) {
  std::vector<size_t> kept;
  for (size_t i = 0; i < points.size(); ++i) {
    if (kept.empty() || (points[i] - points[kept.back()]).norm() > kTouchTolerance) kept.push_back(i);
  }
  if (ring) {
    while (kept.size() > 1 && (points[kept.back()] - points[kept.front()]).norm() <= kTouchTolerance) {
      kept.pop_back();
    }
  }
  return kept;
}

double signedArea(const std::vector<Vec2>& ring) {
  double twice = 0.0;
  for (size_t i = 0; i < ring.size(); ++i) twice += cross(ring[i], ring[(i + 1) % ring.size()]);
  return twice / 2.0;
}

bool onOneLine(const std::vector<Vec2>& points) {
  if (points.empty()) return true;
  const Vec2& a = points.front();
  Vec2 far = a;
  for (const Vec2& p : points) {
    if ((p - a).norm() > (far - a).norm()) far = p;
  }
  for (const Vec2& p : points) {
    if (std::fabs(sideOf(a, far, p)) > kTouchTolerance) return false;
  }
  return true;
}

bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  if (boxesApart(a, b, c, d)) return false;
  return sign(a, b, c) * sign(a, b, d) < 0 && sign(c, d, a) * sign(c, d, b) < 0;
}

bool segmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  if (boxesApart(a, b, c, d)) return false;
  if (segmentsCross(a, b, c, d)) return true;
  const double t = kTouchTolerance;
  return distanceToSegment(a, c, d) <= t || distanceToSegment(b, c, d) <= t || distanceToSegment(c, a, b) <= t ||
         distanceToSegment(d, a, b) <= t;
}

std::optional<std::pair<size_t, size_t>> selfIntersection(const std::vector<Vec2>& ring) {
  const size_t n = ring.size();
  auto side = [&](size_t i, size_t k) { return k == 0 ? ring[i] : ring[(i + 1) % n]; };
  for (size_t i = 0; i < n; ++i) {
    // Neighbours i and i+1 share point i+1; they fold back if the next point lies on the line, behind.
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    const Vec2& c = ring[(i + 2) % n];
    if (sign(a, b, c) == 0 && (b - a).dot(c - b) < 0.0) {
      return std::make_pair(std::min(i, (i + 1) % n), std::max(i, (i + 1) % n));
    }
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through point 0
      if (segmentsMeet(side(i, 0), side(i, 1), side(j, 0), side(j, 1))) return std::make_pair(i, j);
    }
  }
  return std::nullopt;
}

Place locate(const std::vector<Vec2>& ring, const Vec2& p) {
  const size_t n = ring.size();
  bool inside = false;
  for (size_t i = 0; i < n; ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % n];
    if (distanceToSegment(p, a, b) <= kTouchTolerance) return Place::On;
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (x > p.x()) inside = !inside;
    }
  }
  return inside ? Place::Inside : Place::Outside;
}

Vec2 pointJustInside(const std::vector<Vec2>& ring) {
  const size_t n = ring.size();
  size_t longest = 0;
  for (size_t i = 1; i < n; ++i) {
    if ((ring[(i + 1) % n] - ring[i]).norm() > (ring[(longest + 1) % n] - ring[longest]).norm()) longest = i;
  }
  const Vec2& a = ring[longest];
  const Vec2& b = ring[(longest + 1) % n];
  const Vec2 mid = (a + b) / 2.0;
  Vec2 left(-(b - a).y(), (b - a).x());
  left.normalize();
  const Vec2 inward = signedArea(ring) >= 0.0 ? left : Vec2(-left);
  // Start at a thousandth of the side and halve until the point is inside (a very thin polygon).
  for (double step = (b - a).norm() * 1e-3; step > 2.0 * kTouchTolerance; step /= 2.0) {
    const Vec2 p = mid + step * inward;
    if (locate(ring, p) == Place::Inside) return p;
  }
  return mid + 2.0 * kTouchTolerance * inward;
}

}  // namespace nxtmap::sim::polygon
