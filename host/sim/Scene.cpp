// Scene: building the elements' lists, the bucket index, the buckets' reference points and the cover.
// The queries (solidAt, cast, touches) are in SceneQueries.cpp.
#include "host/sim/Scene.hpp"

#include "host/sim/SceneGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace nxtmap::sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kBucketCm = 50.0;         // preferred bucket side, cm
constexpr long kMaxBuckets = 1L << 18;     // the index's bound: buckets grow for scenes beyond ~250 m across
constexpr long kMaxCoverCells = 1L << 20;  // the cover's bound, one byte a cell
constexpr int kCoverPerBucket = 8;         // cover cells a bucket side, at most (6.25 cm cells)
constexpr double kMarginCm = 1.0;          // the indexed box reaches this far past every element, cm
constexpr double kPadCm = 1e-3;            // an element is listed in every bucket it comes this close to, cm
constexpr double kClearCm = 1e-6;          // a bucket's reference point keeps this far from every ring side, cm

// Offsets (fractions of a bucket side) tried in turn for a bucket's reference point; irrational-looking
// so that they rarely fall on a raster's lines.
constexpr double kReferenceFractions[] = {0.5123456789, 0.3183098862, 0.7071067812, 0.2718281828,
                                          0.6180339887, 0.1414213562, 0.8660254038};

// Builds compressed per-bucket lists from (bucket, item) pairs.
void compress(const std::vector<std::pair<int, int>>& pairs, int buckets, std::vector<int>& start,
              std::vector<int>& items) {
  start.assign(static_cast<size_t>(buckets) + 1, 0);
  for (const auto& pair : pairs) ++start[static_cast<size_t>(pair.first) + 1];
  for (size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
  items.assign(pairs.size(), 0);
  std::vector<int> next(start.begin(), start.end() - 1);
  for (const auto& [bucket, item] : pairs) items[static_cast<size_t>(next[static_cast<size_t>(bucket)]++)] = item;
}

}  // namespace

void Scene::addRing(Ring ring) { rings_.push_back(std::move(ring)); }
void Scene::addWall(Edge wall) { walls_.push_back(wall); }
void Scene::addDisc(Disc disc) { discs_.push_back(disc); }

void Scene::finish() {
  edges_.clear();
  segments_.clear();
  for (const Ring& ring : rings_) {
    for (size_t i = 0; i < ring.points.size(); ++i) {
      edges_.push_back(Edge{ring.points[i], ring.points[(i + 1) % ring.points.size()], ring.surface});
    }
  }
  ringEdges_ = edges_.size();
  edges_.insert(edges_.end(), walls_.begin(), walls_.end());
  bounds_ = SceneBounds{kInf, kInf, -kInf, -kInf};
  const auto include = [&](const Vec2& low, const Vec2& high) {
    bounds_ = SceneBounds{std::min(bounds_.minX, low.x()), std::min(bounds_.minY, low.y()),
                          std::max(bounds_.maxX, high.x()), std::max(bounds_.maxY, high.y())};
  };
  for (size_t i = 0; i < edges_.size(); ++i) {
    const Edge& e = edges_[i];
    const Vec2 along = e.b - e.a;
    const double len = along.norm();
    const Vec2 normal = len > 0.0 ? Vec2(Vec2(-along.y(), along.x()) / len) : Vec2(0.0, 0.0);
    segments_.push_back(Segment{e.a, e.b, along, normal, e.a.cwiseMin(e.b), e.a.cwiseMax(e.b),
                                len > 0.0 ? 1.0 / (len * len) : 0.0, i < ringEdges_});
    include(segments_.back().low, segments_.back().high);
  }
  for (const Disc& d : discs_) include(d.centre.array() - d.radiusCm, d.centre.array() + d.radiusCm);
  if (edges_.empty() && discs_.empty()) bounds_ = SceneBounds{};

  const double spanX = bounds_.maxX - bounds_.minX + 2.0 * kMarginCm;
  const double spanY = bounds_.maxY - bounds_.minY + 2.0 * kMarginCm;
  double side = std::max(kBucketCm, std::sqrt(spanX * spanY / static_cast<double>(kMaxBuckets)));
  while (std::ceil(spanX / side) * std::ceil(spanY / side) > 2.0 * static_cast<double>(kMaxBuckets)) {
    side *= 1.5;  // a long thin scene
  }
  const Vec2 corner(bounds_.minX - kMarginCm, bounds_.minY - kMarginCm);
  buckets_ = PlaneGrid(corner, side, std::max(1, static_cast<int>(std::ceil(spanX / side))),
                       std::max(1, static_cast<int>(std::ceil(spanY / side))));
  indexElements();
  placeReferences();
  buildCover();
}

void Scene::indexElements() {
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < segments_.size(); ++i) {
    buckets_.forCellsNearSegment(segments_[i].a, segments_[i].b, kPadCm, [&](int col, int row) {
      pairs.emplace_back(buckets_.index(col, row), static_cast<int>(i));
    });
  }
  compress(pairs, buckets_.cells(), bucketEdges_.start, bucketEdges_.items);
  pairs.clear();
  for (size_t i = 0; i < discs_.size(); ++i) {
    const double reach = discs_[i].radiusCm + kPadCm;
    buckets_.forCellsInBox(discs_[i].centre.array() - reach, discs_[i].centre.array() + reach, [&](int col, int row) {
      pairs.emplace_back(buckets_.index(col, row), static_cast<int>(i));
    });
  }
  compress(pairs, buckets_.cells(), bucketDiscs_.start, bucketDiscs_.items);
}

// Each row of buckets: one horizontal line (clear of every ring side where a bucket's point sits), the
// ring sides' crossings of it sorted, and per bucket a point on the line; the point is inside when an odd
// number of crossings lie to its right (the half-open rule in y counts a vertex on the line once).
void Scene::placeReferences() {
  reference_.assign(static_cast<size_t>(buckets_.cells()), Vec2(0.0, 0.0));
  referenceInside_.assign(static_cast<size_t>(buckets_.cells()), 0);
  const auto clearance = [&](const Vec2& q, size_t b) {
    double clear = kInf;
    for (int k = bucketEdges_.start[b]; k < bucketEdges_.start[b + 1]; ++k) {
      const Segment& s = segments_[static_cast<size_t>(bucketEdges_.items[static_cast<size_t>(k)])];
      if (s.ring) clear = std::min(clear, geometry::pointSegmentDistance(q, s.a, s.b));
    }
    return clear;
  };
  std::vector<double> crossings;
  for (int row = 0; row < buckets_.countY; ++row) {
    double lineY = 0.0;
    for (const double fy : kReferenceFractions) {  // the last try is kept if none is clear everywhere
      lineY = buckets_.origin.y() + (row + fy) * buckets_.cellCm;
      bool allClear = true;
      for (int col = 0; col < buckets_.countX; ++col) {
        const size_t b = static_cast<size_t>(buckets_.index(col, row));
        double best = -1.0;
        for (const double fx : kReferenceFractions) {
          const Vec2 q(buckets_.origin.x() + (col + fx) * buckets_.cellCm, lineY);
          const double clear = clearance(q, b);
          if (clear > best) {
            best = clear;
            reference_[b] = q;
          }
          if (clear > kClearCm) break;
        }
        allClear = allClear && best > kClearCm;
      }
      if (allClear) break;
    }
    const size_t first = static_cast<size_t>(buckets_.index(0, row));
    const size_t last = static_cast<size_t>(buckets_.index(buckets_.countX - 1, row));
    std::vector<int> rowEdges(bucketEdges_.items.begin() + bucketEdges_.start[first],
                              bucketEdges_.items.begin() + bucketEdges_.start[last + 1]);
    std::sort(rowEdges.begin(), rowEdges.end());
    rowEdges.erase(std::unique(rowEdges.begin(), rowEdges.end()), rowEdges.end());
    crossings.clear();
    for (const int i : rowEdges) {
      const Segment& s = segments_[static_cast<size_t>(i)];
      if (!s.ring || (s.a.y() > lineY) == (s.b.y() > lineY)) continue;
      crossings.push_back(s.a.x() + (lineY - s.a.y()) * (s.b.x() - s.a.x()) / (s.b.y() - s.a.y()));
    }
    std::sort(crossings.begin(), crossings.end());
    for (size_t b = first; b <= last; ++b) {
      const auto right = crossings.end() - std::upper_bound(crossings.begin(), crossings.end(), reference_[b].x());
      referenceInside_[b] = static_cast<char>(right % 2 == 1);
    }
  }
}

// Cells an element comes near are marked; every other cell takes the answer at its centre, shared by its
// 4-connected unmarked neighbours (no element lies between two of them).
void Scene::buildCover() {
  const long perBucket =
      static_cast<long>(std::sqrt(static_cast<double>(kMaxCoverCells) / static_cast<double>(buckets_.cells())));
  coverPerBucket_ = static_cast<int>(std::clamp(perBucket, 1L, static_cast<long>(kCoverPerBucket)));
  cover_ = PlaneGrid(buckets_.origin, buckets_.cellCm / coverPerBucket_, buckets_.countX * coverPerBucket_,
                     buckets_.countY * coverPerBucket_);
  coverState_.assign(static_cast<size_t>(cover_.cells()), kCoverUnknown);
  const auto mark = [&](int col, int row) { coverState_[static_cast<size_t>(cover_.index(col, row))] = kCoverNear; };
  for (const Segment& s : segments_) cover_.forCellsNearSegment(s.a, s.b, kPadCm, mark);
  for (const Disc& d : discs_) {
    cover_.forCellsInBox(d.centre.array() - (d.radiusCm + kPadCm), d.centre.array() + (d.radiusCm + kPadCm), mark);
  }
  std::vector<int> stack;
  for (int start = 0; start < cover_.cells(); ++start) {
    if (coverState_[static_cast<size_t>(start)] != kCoverUnknown) continue;
    const int col = start % cover_.countX, row = start / cover_.countX;
    const Vec2 centre = cover_.origin + Vec2(col + 0.5, row + 0.5) * cover_.cellCm;
    const int bucket = buckets_.index(col / coverPerBucket_, row / coverPerBucket_);
    const uint8_t state = solidInBucket(centre, bucket) ? kCoverSolid : kCoverFree;
    coverState_[static_cast<size_t>(start)] = state;
    stack.push_back(start);
    while (!stack.empty()) {
      const int cell = stack.back();
      stack.pop_back();
      const int c = cell % cover_.countX, r = cell / cover_.countX;
      const int next[4][2] = {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}};
      for (const auto& n : next) {
        if (n[0] < 0 || n[1] < 0 || n[0] >= cover_.countX || n[1] >= cover_.countY) continue;
        const size_t i = static_cast<size_t>(cover_.index(n[0], n[1]));
        if (coverState_[i] != kCoverUnknown) continue;
        coverState_[i] = state;
        stack.push_back(static_cast<int>(i));
      }
    }
  }
}

}  // namespace nxtmap::sim
