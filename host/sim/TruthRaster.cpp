#include "host/sim/TruthRaster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace nxtmap::sim {

namespace {

// Grid coordinates (cells) closer than this to a cell border count as on the border: a traced raster's
// sides lie on borders up to the rounding of cm -> cells.
constexpr double kOnBorder = 1e-7;

struct GridSegment {
  Vec2 a, b;  // grid coordinates, cells
};

// True if the closed segment passes through the open square of cell (col, row).
bool crossesInterior(const GridSegment& s, int col, int row) {
  const double lo[2] = {col - 0.5, row - 0.5};
  const double hi[2] = {col + 0.5, row + 0.5};
  const Vec2 d = s.b - s.a;
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 2; ++axis) {  // Liang-Barsky against the closed square
    const double p = s.a[axis], dp = d[axis];
    if (std::fabs(dp) < 1e-15) {
      if (p <= lo[axis] + kOnBorder || p >= hi[axis] - kOnBorder) return false;
      continue;
    }
    double ta = (lo[axis] - p) / dp, tb = (hi[axis] - p) / dp;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  // The clipped piece is a chord of the square: it lies on one side or its middle is inside.
  const Vec2 m = s.a + d * (0.5 * (t0 + t1));
  return m.x() > lo[0] + kOnBorder && m.x() < hi[0] - kOnBorder && m.y() > lo[1] + kOnBorder &&
         m.y() < hi[1] - kOnBorder;
}

class Raster {
 public:
  Raster(int width, int height)
      : w_(width), h_(height), cells_(static_cast<size_t>(width) * static_cast<size_t>(height), 0) {}
  bool inside(int c, int r) const { return c >= 0 && r >= 0 && c < w_ && r < h_; }
  void block(int c, int r) { cells_[static_cast<size_t>(r) * static_cast<size_t>(w_) + static_cast<size_t>(c)] = 1; }
  bool blocked(int c, int r) const {
    return cells_[static_cast<size_t>(r) * static_cast<size_t>(w_) + static_cast<size_t>(c)] != 0;
  }
  int width() const { return w_; }
  int height() const { return h_; }
  std::vector<uint8_t> take() { return std::move(cells_); }

 private:
  int w_, h_;
  std::vector<uint8_t> cells_;
};

int nearestCell(double g) { return static_cast<int>(std::floor(g + 0.5)); }

// Blocks every cell whose interior the segment passes through: row by row, only the cells its x range
// in that row's band can reach.
void blockSegment(const GridSegment& s, Raster& out) {
  const int r0 = std::max(0, nearestCell(std::min(s.a.y(), s.b.y())) - 1);
  const int r1 = std::min(out.height() - 1, nearestCell(std::max(s.a.y(), s.b.y())) + 1);
  const Vec2 d = s.b - s.a;
  for (int r = r0; r <= r1; ++r) {
    double xa = std::min(s.a.x(), s.b.x()), xb = std::max(s.a.x(), s.b.x());
    if (std::fabs(d.y()) > 1e-15) {  // the x range inside the band r - 0.5 .. r + 0.5
      const double ta = std::clamp((r - 0.5 - s.a.y()) / d.y(), 0.0, 1.0);
      const double tb = std::clamp((r + 0.5 - s.a.y()) / d.y(), 0.0, 1.0);
      xa = std::min(s.a.x() + d.x() * ta, s.a.x() + d.x() * tb);
      xb = std::max(s.a.x() + d.x() * ta, s.a.x() + d.x() * tb);
    }
    const int c0 = std::max(0, nearestCell(xa) - 1), c1 = std::min(out.width() - 1, nearestCell(xb) + 1);
    for (int c = c0; c <= c1; ++c) {
      if (!out.blocked(c, r) && crossesInterior(s, c, r)) out.block(c, r);
    }
  }
}

// Blocks every cell whose open square the disc (centre, radius in cells) overlaps.
void blockDisc(const Vec2& centre, double radius, Raster& out) {
  const int c0 = std::max(0, nearestCell(centre.x() - radius)),
            c1 = std::min(out.width() - 1, nearestCell(centre.x() + radius));
  const int r0 = std::max(0, nearestCell(centre.y() - radius)),
            r1 = std::min(out.height() - 1, nearestCell(centre.y() + radius));
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) {
      const double dx = std::max(0.0, std::fabs(centre.x() - c) - 0.5);
      const double dy = std::max(0.0, std::fabs(centre.y() - r) - 0.5);
      if (std::hypot(dx, dy) < radius - kOnBorder) out.block(c, r);
    }
  }
}

// Blocks the cells whose centres lie in solid space by the even-odd rule over the ring sides (an even
// number of sides crossed to the left, none included, is solid). Cells whose interior a side crosses are
// blocked already, so a centre on a side never decides anything.
void blockSolid(const std::vector<GridSegment>& ringSides, Raster& out) {
  std::vector<double> xs;
  for (int r = 0; r < out.height(); ++r) {
    xs.clear();
    for (const GridSegment& s : ringSides) {
      const double ya = s.a.y(), yb = s.b.y();
      if ((ya <= r) == (yb <= r)) continue;  // half-open: each vertex counted once, horizontals never
      xs.push_back(s.a.x() + (r - ya) * (s.b.x() - s.a.x()) / (yb - ya));
    }
    std::sort(xs.begin(), xs.end());
    size_t crossed = 0;
    for (int c = 0; c < out.width(); ++c) {
      while (crossed < xs.size() && xs[crossed] < c) ++crossed;
      if (crossed % 2 == 0) out.block(c, r);
    }
  }
}

}  // namespace

World rasterizeScene(const Scene& scene, const GridFrame& frame, int width, int height, const std::string& name) {
  Raster out(width, height);
  std::vector<GridSegment> ringSides;
  for (const Ring& ring : scene.rings()) {
    const size_t n = ring.points.size();
    for (size_t i = 0; i < n; ++i) {
      ringSides.push_back({frame.toGrid(ring.points[i]), frame.toGrid(ring.points[(i + 1) % n])});
    }
  }
  for (const GridSegment& s : ringSides) blockSegment(s, out);
  for (const Edge& wall : scene.walls()) blockSegment({frame.toGrid(wall.a), frame.toGrid(wall.b)}, out);
  for (const Disc& disc : scene.discs()) blockDisc(frame.toGrid(disc.centre), disc.radiusCm / frame.cellCm, out);
  blockSolid(ringSides, out);
  return World::fromCells(width, height, frame.cellCm / 100.0, name, out.take());
}

Placement placeOnGrid(const Scene& scene, const Vec2& startCm, double frameHeadingDeg, double cellCm) {
  GridFrame atStart;
  atStart.originCm = startCm;
  atStart.headingDeg = frameHeadingDeg;
  atStart.cellCm = cellCm;
  const SceneBounds b = scene.bounds();
  double minC = 0.0, maxC = 0.0, minR = 0.0, maxR = 0.0;  // grid coordinates; the start is (0, 0)
  for (const Vec2& corner : {Vec2(b.minX, b.minY), Vec2(b.maxX, b.minY), Vec2(b.minX, b.maxY), Vec2(b.maxX, b.maxY)}) {
    const Vec2 g = atStart.toGrid(corner);
    minC = std::min(minC, g.x());
    maxC = std::max(maxC, g.x());
    minR = std::min(minR, g.y());
    maxR = std::max(maxR, g.y());
  }
  // First and last cells the bounds reach into (a bound on a border reaches no further), then the margin.
  const int c0 = static_cast<int>(std::floor(minC + 0.5 + kOnBorder)) - 1;
  const int c1 = static_cast<int>(std::ceil(maxC - 0.5 - kOnBorder)) + 1;
  const int r0 = static_cast<int>(std::floor(minR + 0.5 + kOnBorder)) - 1;
  const int r1 = static_cast<int>(std::ceil(maxR - 0.5 - kOnBorder)) + 1;
  Placement p;
  p.frame = atStart;
  p.frame.originCm = atStart.toPlane(Vec2(c0, r0));
  p.startCol = -c0;
  p.startRow = -r0;
  p.width = c1 - c0 + 1;
  p.height = r1 - r0 + 1;
  return p;
}

}  // namespace nxtmap::sim
