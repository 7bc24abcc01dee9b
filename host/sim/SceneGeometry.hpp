// SceneGeometry: the plane primitives Scene is built from: rays against segments and discs, distances,
// segment contact and the convex point test. Plane coordinates in centimetres (x right, y down).
#pragma once

#include "host/sim/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace nxtmap::sim::geometry {

// Two points closer than this (cm) touch: "a point on an element" in Scene's sense.
constexpr double kTouchCm = 1e-9;

inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Ray parameter (distance along unit d) where the ray from o meets segment ab, or +infinity. End points
// count (within a relative 1e-12 of the segment's length); a segment lying along the ray is met at its
// nearer end.
inline double raySegment(const Vec2& o, const Vec2& d, const Vec2& a, const Vec2& b) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Vec2 e = b - a;
  const Vec2 ao = a - o;
  const double denom = cross(d, e);
  if (denom == 0.0) {  // parallel: met only if collinear, at the nearer end ahead
    if (cross(ao, d) != 0.0) return kInf;
    const double ta = ao.dot(d), tb = (b - o).dot(d);
    if (ta < 0.0 && tb < 0.0) return kInf;
    if (ta < 0.0 || tb < 0.0) return 0.0;  // the origin lies on the segment
    return std::min(ta, tb);
  }
  const double t = cross(ao, e) / denom;
  const double s = cross(ao, d) / denom;
  constexpr double kEndSlack = 1e-12;
  if (t < 0.0 || s < -kEndSlack || s > 1.0 + kEndSlack) return kInf;
  return t;
}

// Ray parameter where the ray from o (outside the disc) first meets the circle, or +infinity.
inline double rayDisc(const Vec2& o, const Vec2& d, const Vec2& centre, double radius) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Vec2 f = o - centre;
  const double b = f.dot(d);
  const double disc = b * b - (f.squaredNorm() - radius * radius);
  if (disc < 0.0) return kInf;
  const double t = -b - std::sqrt(disc);
  return t >= 0.0 ? t : kInf;
}

// Distance from p to segment ab, cm.
inline double pointSegmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double len2 = e.squaredNorm();
  const double s = len2 > 0.0 ? std::clamp((p - a).dot(e) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + s * e)).norm();
}

// True if segments ab and cd cross or come within kTouchCm of one another.
inline bool segmentsTouch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
  const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
  if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0))) {
    return true;
  }
  const double near = std::min(std::min(pointSegmentDistance(c, a, b), pointSegmentDistance(d, a, b)),
                               std::min(pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d)));
  return near <= kTouchCm;
}

// True if p lies inside the convex polygon (either winding) or within kTouchCm of its boundary.
inline bool insideConvex(const std::vector<Vec2>& poly, const Vec2& p) {
  bool anyLeft = false, anyRight = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2& a = poly[j];
    const Vec2& b = poly[i];
    if (pointSegmentDistance(p, a, b) <= kTouchCm) return true;
    const double side = cross(b - a, p - a);
    anyLeft = anyLeft || side > 0.0;
    anyRight = anyRight || side < 0.0;
  }
  return !(anyLeft && anyRight);
}

// Side of point v against the directed line q->p, with 0 counted as the negative side: every use of one
// vertex against one line agrees, so a vertex lying on the line is moved off it consistently.
inline bool leftOf(const Vec2& q, const Vec2& p, const Vec2& v) { return cross(p - q, v - q) > 0.0; }

}  // namespace nxtmap::sim::geometry
