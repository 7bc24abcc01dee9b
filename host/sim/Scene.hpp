// Scene: the simulated world as continuous geometry, independent of any robot's grid.
// Plane coordinates in centimetres: x grows to the right, y grows DOWN (as World rows and SimRobot);
// directions are compass degrees clockwise from north (0 = towards smaller y, 90 = towards larger x).
// File formats give metres (and y up); their loaders convert.
//
// Three kinds of element, each with a Surface:
// - rings: closed polygons. Solid space is decided by the even-odd rule over all rings, with the plane
//   outside every ring solid: a room's outline encloses free space, a sofa's outline inside it is solid
//   again. (A raster world traces each blocked/free boundary into rings: outside the map is solid.)
// - walls: open segments of no thickness (a curtain, a thin board): solid only along themselves.
// - circles: solid discs (table legs, poles).
// The scene owns its elements; a bucket index over them (built by finish()) keeps ray casts and body
// tests proportional to what lies near the ray or the body.
#pragma once

#include "host/sim/PlaneGrid.hpp"
#include "host/sim/Surface.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace nxtmap::sim {

using Vec2 = Eigen::Vector2d;  // plane point or direction, cm

struct Edge {
  Vec2 a, b;  // end points, cm
  Surface surface = Surface::Hard;
};

struct Ring {
  std::vector<Vec2> points;  // >= 3 vertices, closed implicitly (last joins first), cm
  Surface surface = Surface::Hard;
};

struct Disc {
  Vec2 centre;
  double radiusCm = 0.0;  // > 0
  Surface surface = Surface::Thin;
};

struct SceneHit {
  bool hit = false;           // false: nothing within the range
  double distanceCm = 0.0;    // from the ray's origin to the hit point, cm (0 if the origin is solid)
  double incidenceDeg = 0.0;  // 0..90: angle between the ray and the surface normal at the hit
  Surface surface = Surface::Hard;
  Vec2 normal{0.0, 0.0};  // unit normal at the hit, facing the ray's origin
};

struct SceneBounds {
  double minX = 0.0, minY = 0.0, maxX = 0.0, maxY = 0.0;  // cm, the box around every element
};

class Scene {
 public:
  void addRing(Ring ring);
  void addWall(Edge wall);
  void addDisc(Disc disc);
  // Builds the bucket index; call once after the last add (adding afterwards needs another finish()).
  void finish();

  const std::vector<Ring>& rings() const { return rings_; }
  const std::vector<Edge>& walls() const { return walls_; }
  const std::vector<Disc>& discs() const { return discs_; }
  SceneBounds bounds() const { return bounds_; }

  // Every straight piece: the rings' sides followed by the walls (discs excluded).
  const std::vector<Edge>& edges() const { return edges_; }

  // Nearest element met by the ray from `origin` towards compass `deg`, no farther than maxCm.
  SceneHit cast(const Vec2& origin, double deg, double maxCm) const;
  // True where the even-odd rule over the rings says solid, or inside a disc. A point exactly on an
  // element counts as solid.
  bool solidAt(const Vec2& p) const;
  // True if the convex polygon `body` (>= 3 points, cm) touches any element or holds a solid point
  // (its centroid solid). Used for a robot's footprint; a body of one point tests solidAt.
  bool touches(const std::vector<Vec2>& body) const;

 private:
  // Per-bucket lists, compressed: the items of bucket b are items[start[b] .. start[b + 1]).
  struct BucketLists {
    std::vector<int> start;  // buckets + 1 offsets
    std::vector<int> items;  // indices into edges_ or discs_
  };
  // Per edge, what the queries read, packed together: end points, b - a, the unit normal (left of a->b),
  // the box around a and b, 1 / |b - a|^2 (0 for a point), and whether it is a ring side.
  struct Segment {
    Vec2 a, b, along, normal, low, high;
    double invLength2 = 0.0;
    bool ring = false;
  };
  // The nearest element met so far by a cast: ray parameter (cm) and edge index, or -1 - disc index.
  struct Nearest {
    double t;
    int element;
  };
  enum CoverState : uint8_t { kCoverFree = 0, kCoverSolid = 1, kCoverNear = 2, kCoverUnknown = 3 };

  void indexElements();
  void placeReferences();
  void buildCover();
  // solidAt for p within bucket b: on an element, in a disc, or outside an odd number of rings (counted
  // from the bucket's reference point).
  bool solidInBucket(const Vec2& p, int bucket) const;
  // The elements of bucket b met by the ray (origin o, unit direction d) no farther than maxCm; keeps the
  // nearer of them and best.
  void castInBucket(int bucket, const Vec2& o, const Vec2& d, double maxCm, Nearest& best) const;
  SceneHit hitOf(const Nearest& best, const Vec2& o, const Vec2& d) const;
  bool touchesNear(const std::vector<Vec2>& body, const Vec2& low, const Vec2& high) const;

  std::vector<Ring> rings_;
  std::vector<Edge> walls_;
  std::vector<Disc> discs_;
  std::vector<Edge> edges_;
  std::vector<Segment> segments_;  // per edge
  size_t ringEdges_ = 0;           // edges_[0, ringEdges_) are ring sides, the rest walls
  SceneBounds bounds_;
  // The bucket index over the elements' box (with a margin): every edge and disc is listed in each
  // bucket it comes near (PlaneGrid::forCellsNearSegment).
  PlaneGrid buckets_;
  BucketLists bucketEdges_;
  BucketLists bucketDiscs_;
  std::vector<Vec2> reference_;        // per bucket: a point inside it on no ring side
  std::vector<char> referenceInside_;  // per bucket: 1 if the reference lies inside an odd number of rings
  // The cover: a finer grid over the same box (coverPerBucket_ cells a bucket side); a cell near no
  // element is known free or solid as a whole, so most solidAt calls need no geometry.
  PlaneGrid cover_;
  int coverPerBucket_ = 1;
  std::vector<uint8_t> coverState_;  // per cover cell, a CoverState
};

}  // namespace nxtmap::sim
