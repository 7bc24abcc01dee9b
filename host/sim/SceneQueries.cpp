// Scene's queries: solidAt, cast and touches, over the index that Scene.cpp builds.
#include "host/sim/Scene.hpp"

#include "host/sim/RayCast.hpp"
#include "host/sim/SceneGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nxtmap::sim {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEndSlack = 1e-12;  // a segment's end points count, as in geometry::raySegment
using geometry::cross;
}  // namespace

bool Scene::solidInBucket(const Vec2& p, int bucket) const {
  const size_t bk = static_cast<size_t>(bucket);
  for (int k = bucketDiscs_.start[bk]; k < bucketDiscs_.start[bk + 1]; ++k) {
    const Disc& d = discs_[static_cast<size_t>(bucketDiscs_.items[static_cast<size_t>(k)])];
    if ((p - d.centre).norm() <= d.radiusCm + geometry::kTouchCm) return true;
  }
  // Even-odd: the reference point's answer, flipped by every ring side crossing the segment from it to p
  // (a vertex on that segment's line counts on one side for every side it ends: see geometry::leftOf).
  // Only a side whose box meets the box of q..p (widened by kTouchCm) can hold p or cross q..p.
  const Vec2& q = reference_[bk];
  bool inside = referenceInside_[bk] != 0;
  const Vec2 low = q.cwiseMin(p).array() - geometry::kTouchCm, high = q.cwiseMax(p).array() + geometry::kTouchCm;
  for (int k = bucketEdges_.start[bk]; k < bucketEdges_.start[bk + 1]; ++k) {
    const Segment& s = segments_[static_cast<size_t>(bucketEdges_.items[static_cast<size_t>(k)])];
    if (s.high.x() < low.x() || s.high.y() < low.y() || s.low.x() > high.x() || s.low.y() > high.y()) continue;
    const double side = cross(s.along, p - s.a);  // |b - a| times p's signed distance from the line
    if (side * side * s.invLength2 <= geometry::kTouchCm * geometry::kTouchCm &&
        geometry::pointSegmentDistance(p, s.a, s.b) <= geometry::kTouchCm) {
      return true;  // on the element
    }
    if (!s.ring || geometry::leftOf(q, p, s.a) == geometry::leftOf(q, p, s.b)) continue;
    if ((cross(s.along, q - s.a) > 0.0) != (side > 0.0)) inside = !inside;
  }
  return !inside;
}

bool Scene::solidAt(const Vec2& p) const {
  int col = 0, row = 0;
  if (!cover_.cellOf(p, col, row)) return true;  // outside the index: outside every ring
  const uint8_t state = coverState_[static_cast<size_t>(cover_.index(col, row))];
  if (state != kCoverNear) return state == kCoverSolid;
  return solidInBucket(p, buckets_.index(col / coverPerBucket_, row / coverPerBucket_));
}

// Division-free rejection first: with denom = cross(d, b - a) made positive, the ray meets the segment at
// t = cross(a - o, b - a) / denom and s = cross(a - o, d) / denom along it.
void Scene::castInBucket(int bucket, const Vec2& o, const Vec2& d, double maxCm, Nearest& best) const {
  const size_t b = static_cast<size_t>(bucket);
  for (int k = bucketEdges_.start[b]; k < bucketEdges_.start[b + 1]; ++k) {
    const int i = bucketEdges_.items[static_cast<size_t>(k)];
    const Segment& s = segments_[static_cast<size_t>(i)];
    const double aox = s.a.x() - o.x(), aoy = s.a.y() - o.y();
    const double denom = d.x() * s.along.y() - d.y() * s.along.x();
    if (denom == 0.0) {  // parallel: only a segment along the ray is met
      const double t = geometry::raySegment(o, d, s.a, s.b);
      if (t <= maxCm && t < best.t) best = Nearest{t, i};
      continue;
    }
    const double sign = denom < 0.0 ? -1.0 : 1.0;
    const double den = sign * denom, nt = sign * (aox * s.along.y() - aoy * s.along.x());
    const double ns = sign * (aox * d.y() - aoy * d.x());
    const bool met = (nt >= 0.0) & (ns >= -kEndSlack * den) & (ns <= (1.0 + kEndSlack) * den);
    const double t = met ? nt / den : kInf;
    if (t <= maxCm && t < best.t) best = Nearest{t, i};
  }
  for (int k = bucketDiscs_.start[b]; k < bucketDiscs_.start[b + 1]; ++k) {
    const int i = bucketDiscs_.items[static_cast<size_t>(k)];
    const Disc& disc = discs_[static_cast<size_t>(i)];
    const double t = geometry::rayDisc(o, d, disc.centre, disc.radiusCm);
    if (t <= maxCm && t < best.t) best = Nearest{t, -1 - i};
  }
}

SceneHit Scene::hitOf(const Nearest& best, const Vec2& o, const Vec2& d) const {
  if (best.t == kInf) return SceneHit{};
  Vec2 normal(0.0, 0.0);
  Surface surface = Surface::Hard;
  if (best.element >= 0) {
    normal = segments_[static_cast<size_t>(best.element)].normal;
    surface = edges_[static_cast<size_t>(best.element)].surface;
  } else {
    const Disc& disc = discs_[static_cast<size_t>(-1 - best.element)];
    normal = (o + best.t * d - disc.centre) / disc.radiusCm;
    surface = disc.surface;
  }
  if (normal.dot(d) > 0.0) normal = -normal;  // towards the origin
  const double cosInc = std::fmin(1.0, std::fabs(d.dot(normal)));
  return SceneHit{true, best.t, std::acos(cosInc) * 180.0 / kPi, surface, normal};
}

// The buckets along the ray in order (Amanatides-Woo over the bucket grid); the walk stops at the first
// bucket whose nearest hit lies before the ray leaves it.
SceneHit Scene::cast(const Vec2& origin, double deg, double maxCm) const {
  double dx = 0.0, dy = 0.0;
  directionVector(deg, dx, dy);
  const Vec2 d(dx, dy);
  int col = 0, row = 0;
  if (solidAt(origin) || !buckets_.cellOf(origin, col, row)) return SceneHit{true, 0.0, 0.0, Surface::Hard, Vec2(-d)};
  const double side = buckets_.cellCm;
  const int stepX = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int stepY = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  const double ox = origin.x() - buckets_.origin.x(), oy = origin.y() - buckets_.origin.y();
  double tMaxX = stepX > 0 ? ((col + 1) * side - ox) / dx : (stepX < 0 ? (col * side - ox) / dx : kInf);
  double tMaxY = stepY > 0 ? ((row + 1) * side - oy) / dy : (stepY < 0 ? (row * side - oy) / dy : kInf);
  const double tDeltaX = stepX != 0 ? side / std::fabs(dx) : kInf;
  const double tDeltaY = stepY != 0 ? side / std::fabs(dy) : kInf;
  Nearest best{kInf, 0};
  while (true) {
    castInBucket(buckets_.index(col, row), origin, d, maxCm, best);
    const double exit = std::min(tMaxX, tMaxY);
    if (best.t <= exit || exit > maxCm) break;
    if (tMaxX < tMaxY) {
      col += stepX;
      tMaxX += tDeltaX;
    } else {
      row += stepY;
      tMaxY += tDeltaY;
    }
    if (col < 0 || row < 0 || col >= buckets_.countX || row >= buckets_.countY) break;
  }
  return hitOf(best, origin, d);
}

bool Scene::touches(const std::vector<Vec2>& body) const {
  if (body.empty()) return false;
  Vec2 centroid(0.0, 0.0);
  for (const Vec2& p : body) centroid += p;
  centroid /= static_cast<double>(body.size());
  const bool solidCentroid = solidAt(centroid);
  if (body.size() == 1 || solidCentroid) return solidCentroid;
  Vec2 low = body[0], high = body[0];
  for (const Vec2& p : body) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return touchesNear(body, low, high);
}

// The centroid is free, so it lies within the index; the body's box is clamped to it (no element lies
// beyond). An element touches if it meets a side of the body or lies inside it.
bool Scene::touchesNear(const std::vector<Vec2>& body, const Vec2& low, const Vec2& high) const {
  std::vector<int> edges, discs;
  buckets_.forCellsInBox(low.array() - geometry::kTouchCm, high.array() + geometry::kTouchCm, [&](int col, int row) {
    const size_t b = static_cast<size_t>(buckets_.index(col, row));
    edges.insert(edges.end(), bucketEdges_.items.begin() + bucketEdges_.start[b],
                 bucketEdges_.items.begin() + bucketEdges_.start[b + 1]);
    discs.insert(discs.end(), bucketDiscs_.items.begin() + bucketDiscs_.start[b],
                 bucketDiscs_.items.begin() + bucketDiscs_.start[b + 1]);
  });
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::sort(discs.begin(), discs.end());
  discs.erase(std::unique(discs.begin(), discs.end()), discs.end());
  const bool area = body.size() >= 3;
  const size_t sides = area ? body.size() : 1;  // two points: one segment
  for (const int i : edges) {
    const Segment& s = segments_[static_cast<size_t>(i)];
    if (area && geometry::insideConvex(body, s.a)) return true;
    for (size_t k = 0; k < sides; ++k) {
      if (geometry::segmentsTouch(s.a, s.b, body[k], body[(k + 1) % body.size()])) return true;
    }
  }
  for (const int i : discs) {
    const Disc& d = discs_[static_cast<size_t>(i)];
    if (area && geometry::insideConvex(body, d.centre)) return true;
    for (size_t k = 0; k < sides; ++k) {
      const double gap = geometry::pointSegmentDistance(d.centre, body[k], body[(k + 1) % body.size()]);
      if (gap <= d.radiusCm + geometry::kTouchCm) return true;
    }
  }
  return false;
}

}  // namespace nxtmap::sim
