#include "host/sim/WorldDraft.hpp"

#include "host/sim/PolygonCheck.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

namespace nxtmap::sim {

namespace {

using polygon::Place;

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinAreaM2 = 1e-6;  // a polygon of less area (a square millimetre) is a line drawn twice

std::string metres(const Vec2& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%g, %g) m", p.x(), p.y());
  return buf;
}

std::string field(const DraftShape& s) {
  switch (s.kind) {
    case DraftShape::Kind::Polygon: return "polygon";
    case DraftShape::Kind::Circle: return "circle";
    case DraftShape::Kind::Wall: return "wall";
  }
  return "polygon";
}

std::string pointName(const DraftShape& s, size_t i) { return field(s) + "[" + std::to_string(i) + "]"; }

// The shape's distinct points.
std::vector<Vec2> distinct(const DraftShape& s) {
  std::vector<Vec2> out;
  for (const size_t i : s.kept) out.push_back(s.points[i]);
  return out;
}

// "side polygon[1]-polygon[2]": side k of the distinct points, named by the points as written.
std::string sideName(const DraftShape& s, size_t k) {
  const size_t from = s.kept[k], to = s.kept[(k + 1) % s.kept.size()];
  return "side " + pointName(s, from) + "-" + pointName(s, to);
}

std::string checkPolygon(DraftShape& s) {
  s.kept = polygon::distinctPoints(s.points, true);
  if (s.kept.size() < 3) {
    return s.where() + ": polygon is open or degenerate: it needs at least 3 distinct points, has " +
           std::to_string(s.kept.size());
  }
  const std::vector<Vec2> ring = distinct(s);
  if (polygon::onOneLine(ring)) return s.where() + ": polygon has no area (its points lie on one line)";
  if (const auto pair = polygon::selfIntersection(ring)) {
    return s.where() + ": polygon crosses itself: " + sideName(s, pair->first) + " meets " + sideName(s, pair->second);
  }
  if (std::fabs(polygon::signedArea(ring)) < kMinAreaM2) return s.where() + ": polygon has almost no area";
  return "";
}

std::string checkWall(DraftShape& s) {
  s.kept = polygon::distinctPoints(s.points, false);
  if (s.kept.size() < 2) {
    return s.where() + ": wall needs at least 2 distinct points, has " + std::to_string(s.kept.size());
  }
  return "";
}

// The shape lies inside the outline or on it: every point and side middle not outside, no side crossing.
std::string checkInside(const DraftShape& s, const std::vector<Vec2>& outline) {
  const std::vector<Vec2> pts = distinct(s);
  for (size_t k = 0; k < pts.size(); ++k) {
    if (polygon::locate(outline, pts[k]) == Place::Outside) {
      const std::string what = s.kind == DraftShape::Kind::Circle ? "circle centre" : pointName(s, s.kept[k]);
      return s.where() + ": " + what + " " + metres(pts[k]) + " lies outside the outline";
    }
  }
  const size_t sides = s.kind == DraftShape::Kind::Polygon ? pts.size() : pts.size() - 1;
  for (size_t k = 0; k < sides; ++k) {
    const Vec2& a = pts[k];
    const Vec2& b = pts[(k + 1) % pts.size()];
    bool crosses = polygon::locate(outline, (a + b) / 2.0) == Place::Outside;
    for (size_t j = 0; j < outline.size() && !crosses; ++j) {
      crosses = polygon::segmentsCross(a, b, outline[j], outline[(j + 1) % outline.size()]);
    }
    if (crosses) return s.where() + ": " + sideName(s, k) + " crosses the outline";
  }
  return "";
}

// True if polygons p and q (distinct points) share some area, not only sides or corners.
bool overlap(const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
  for (size_t i = 0; i < p.size(); ++i) {
    for (size_t j = 0; j < q.size(); ++j) {
      if (polygon::segmentsCross(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()])) return true;
    }
  }
  auto anyInside = [](const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    for (const Vec2& v : a) {
      if (polygon::locate(b, v) == Place::Inside) return true;
    }
    return polygon::locate(b, polygon::pointJustInside(a)) == Place::Inside;
  };
  return anyInside(p, q) || anyInside(q, p);
}

struct Box {
  Vec2 lo, hi;
  bool apart(const Box& o) const {
    return hi.x() < o.lo.x() || o.hi.x() < lo.x() || hi.y() < o.lo.y() || o.hi.y() < lo.y();
  }
};

Box boxOf(const std::vector<Vec2>& pts) {
  Box b{pts.front(), pts.front()};
  for (const Vec2& p : pts) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

std::string checkOverlaps(const WorldDraft& d) {
  std::vector<size_t> polys;
  for (size_t i = 0; i < d.obstacles.size(); ++i) {
    if (d.obstacles[i].kind == DraftShape::Kind::Polygon) polys.push_back(i);
  }
  std::vector<std::vector<Vec2>> rings;
  std::vector<Box> boxes;
  for (const size_t i : polys) {
    rings.push_back(distinct(d.obstacles[i]));
    boxes.push_back(boxOf(rings.back()));
  }
  for (size_t a = 0; a < polys.size(); ++a) {
    for (size_t b = 0; b < a; ++b) {
      if (boxes[a].apart(boxes[b]) || !overlap(rings[a], rings[b])) continue;
      return d.obstacles[polys[a]].where() + ": polygon overlaps " + d.obstacles[polys[b]].label +
             " (overlapping polygons cancel under the even-odd rule: draw them as one)";
    }
  }
  return "";
}

Vec2 transformed(const WorldDraft& d, const Vec2& p) {
  const double rad = d.rotateDeg * kPi / 180.0;
  const double c = std::cos(rad), s = std::sin(rad);
  return Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()) + d.offsetM;
}

std::vector<Vec2> planeRing(const WorldDraft& d, const DraftShape& s) {
  std::vector<Vec2> out;
  for (const Vec2& p : distinct(s)) out.push_back(fileToPlaneCm(transformed(d, p)));
  return out;
}

}  // namespace

std::string checkShapes(WorldDraft& d) {
  if (std::string why = checkPolygon(d.outline); !why.empty()) return why;
  const std::vector<Vec2> outline = distinct(d.outline);
  const Box box = boxOf(outline);
  if (box.hi.x() - box.lo.x() > kMaxExtentM || box.hi.y() - box.lo.y() > kMaxExtentM) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g x %g m", box.hi.x() - box.lo.x(), box.hi.y() - box.lo.y());
    return d.outline.where() + ": the outline spans " + buf + "; a world is at most " +
           std::to_string(static_cast<int>(kMaxExtentM)) + " m a side";
  }
  for (DraftShape& s : d.obstacles) {
    std::string why;
    if (s.kind == DraftShape::Kind::Polygon) why = checkPolygon(s);
    if (s.kind == DraftShape::Kind::Wall) why = checkWall(s);
    if (s.kind == DraftShape::Kind::Circle) s.kept = {0};
    if (why.empty()) why = checkInside(s, outline);
    if (!why.empty()) return why;
  }
  return checkOverlaps(d);
}

WorldSpec buildWorld(const WorldDraft& d) {
  auto scene = std::make_shared<Scene>();
  scene->addRing(Ring{planeRing(d, d.outline), d.outline.surface});
  for (const DraftShape& s : d.obstacles) {
    const std::vector<Vec2> pts = planeRing(d, s);
    if (s.kind == DraftShape::Kind::Polygon) scene->addRing(Ring{pts, s.surface});
    if (s.kind == DraftShape::Kind::Circle) scene->addDisc(Disc{pts.front(), 100.0 * s.radiusM, s.surface});
    if (s.kind == DraftShape::Kind::Wall) {
      for (size_t k = 0; k + 1 < pts.size(); ++k) scene->addWall(Edge{pts[k], pts[k + 1], s.surface});
    }
  }
  scene->finish();
  WorldSpec w;
  w.name = d.name;
  w.scene = scene;
  w.hasStart = d.hasStart;
  w.startCm = fileToPlaneCm(d.startM);
  const double heading = std::fmod(90.0 - d.startYawDeg, 360.0);
  w.startHeadingDeg = heading < 0.0 ? heading + 360.0 : heading;
  return w;
}

std::string checkStart(const WorldDraft& d, const WorldSpec& w) {
  if (!d.hasStart) return "";
  const std::string at = d.startWhere + ": " + metres(d.startM);
  const Place inRoom = polygon::locate(planeRing(d, d.outline), w.startCm);
  if (inRoom == Place::On) return at + " lies on the outline";
  if (inRoom == Place::Outside) return at + " lies outside the outline";
  for (const DraftShape& s : d.obstacles) {
    const std::vector<Vec2> pts = planeRing(d, s);
    bool hit = false;
    if (s.kind == DraftShape::Kind::Polygon) hit = polygon::locate(pts, w.startCm) != Place::Outside;
    if (s.kind == DraftShape::Kind::Circle) hit = (w.startCm - pts.front()).norm() <= 100.0 * s.radiusM;
    for (size_t k = 0; s.kind == DraftShape::Kind::Wall && k + 1 < pts.size(); ++k) {
      hit = hit || polygon::segmentsMeet(w.startCm, w.startCm, pts[k], pts[k + 1]);
    }
    if (hit) return at + " lies inside or on " + s.label;
  }
  if (w.scene->solidAt(w.startCm)) return at + " lies in solid space";
  return "";
}

}  // namespace nxtmap::sim
