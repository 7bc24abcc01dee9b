#include "host/mapping/MapAlignment.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>
#include <tuple>

#include "host/sim/TruthRaster.hpp"

namespace nxtmap::mapping {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfDiagonal = 0.70710678118654752;  // cells: centre to corner
constexpr long kMaxSamples = 2000000;                  // field size bound (8 MB of floats)

double pointSegmentDistance(const sim::Vec2& p, const sim::Vec2& a, const sim::Vec2& b) {
  const sim::Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 <= 0.0 ? 0.0 : std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
  return (p - (a + d * t)).norm();
}

// Per plane lattice point (axis-aligned, stepCm apart): the distance to the nearest obstacle, in cells
// (0 in solid space, capped a little past half a diagonal). at() interpolates it bilinearly and turns it
// into how likely a cell centred there holds an obstacle by the safe rule: 1 within 0.35 cell, 0 from half
// a cell on (a free cell beside a wall on its border lies there; a corner clipped by a wall, up to half a
// diagonal away, is missed: the exact count settles those). Outside the lattice (beyond the scene) 1: solid.
class ObstacleField {
 public:
  ObstacleField(const sim::Scene& scene, double cellCm) : cellCm_(cellCm) {
    const sim::SceneBounds b = scene.bounds();
    minX_ = b.minX - 2.0 * cellCm;
    minY_ = b.minY - 2.0 * cellCm;
    const double w = b.maxX - b.minX + 4.0 * cellCm, h = b.maxY - b.minY + 4.0 * cellCm;
    step_ = std::max(cellCm / 8.0, std::sqrt(w * h / static_cast<double>(kMaxSamples)));
    nx_ = static_cast<long>(std::ceil(w / step_)) + 1;
    ny_ = static_cast<long>(std::ceil(h / step_)) + 1;
    dist_.assign(static_cast<size_t>(nx_ * ny_), static_cast<float>(capCm()));
    for (const sim::Ring& ring : scene.rings()) {
      for (size_t i = 0; i < ring.points.size(); ++i) {
        addSegment(ring.points[i], ring.points[(i + 1) % ring.points.size()]);
      }
    }
    for (const sim::Edge& wall : scene.walls()) addSegment(wall.a, wall.b);
    for (const sim::Disc& disc : scene.discs()) addDisc(disc);
    markSolid(scene);
    for (float& d : dist_) d = static_cast<float>(d / cellCm_);
  }

  double at(double x, double y) const {
    const double gx = (x - minX_) / step_, gy = (y - minY_) / step_;
    const long i = static_cast<long>(std::floor(gx)), j = static_cast<long>(std::floor(gy));
    if (i < 0 || j < 0 || i + 1 >= nx_ || j + 1 >= ny_) return 1.0;
    const double fx = gx - static_cast<double>(i), fy = gy - static_cast<double>(j);
    const float* p = &dist_[static_cast<size_t>(j * nx_ + i)];
    const double top = p[0] + (p[1] - p[0]) * fx, bottom = p[nx_] + (p[nx_ + 1] - p[nx_]) * fx;
    return likelihood(top + (bottom - top) * fy);
  }

 private:
  static double likelihood(double dCells) { return std::clamp((0.5 - dCells) / 0.15, 0.0, 1.0); }
  double capCm() const { return kHalfDiagonal * cellCm_ + 2.0 * step_; }
  double sx(long i) const { return minX_ + static_cast<double>(i) * step_; }
  double sy(long j) const { return minY_ + static_cast<double>(j) * step_; }
  long clampI(double x) const { return std::clamp(static_cast<long>(std::floor((x - minX_) / step_)), 0L, nx_ - 1); }
  long clampJ(double y) const { return std::clamp(static_cast<long>(std::floor((y - minY_) / step_)), 0L, ny_ - 1); }
  float& cell(long i, long j) { return dist_[static_cast<size_t>(j * nx_ + i)]; }

  void addSegment(const sim::Vec2& a, const sim::Vec2& b) {
    const double cap = capCm();
    for (long j = clampJ(std::min(a.y(), b.y()) - cap); j <= clampJ(std::max(a.y(), b.y()) + cap) + 1 && j < ny_; ++j) {
      for (long i = clampI(std::min(a.x(), b.x()) - cap); i <= clampI(std::max(a.x(), b.x()) + cap) + 1 && i < nx_;
           ++i) {
        float& d = cell(i, j);
        d = std::min(d, static_cast<float>(pointSegmentDistance(sim::Vec2(sx(i), sy(j)), a, b)));
      }
    }
  }
  void addDisc(const sim::Disc& disc) {
    const double reach = disc.radiusCm + capCm();
    for (long j = clampJ(disc.centre.y() - reach); j <= clampJ(disc.centre.y() + reach); ++j) {
      for (long i = clampI(disc.centre.x() - reach); i <= clampI(disc.centre.x() + reach); ++i) {
        const double d = std::max(0.0, (sim::Vec2(sx(i), sy(j)) - disc.centre).norm() - disc.radiusCm);
        cell(i, j) = std::min(cell(i, j), static_cast<float>(d));
      }
    }
  }
  // Even-odd rule over the rings, the plane outside every ring solid: distance 0 inside solid space.
  void markSolid(const sim::Scene& scene) {
    std::vector<double> xs;
    for (long j = 0; j < ny_; ++j) {
      const double y = sy(j);
      xs.clear();
      for (const sim::Ring& ring : scene.rings()) {
        for (size_t k = 0; k < ring.points.size(); ++k) {
          const sim::Vec2& a = ring.points[k];
          const sim::Vec2& b = ring.points[(k + 1) % ring.points.size()];
          if ((a.y() <= y) == (b.y() <= y)) continue;
          xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
        }
      }
      std::sort(xs.begin(), xs.end());
      size_t crossed = 0;
      for (long i = 0; i < nx_; ++i) {
        while (crossed < xs.size() && xs[crossed] < sx(i)) ++crossed;
        if (crossed % 2 == 0) cell(i, j) = 0.0f;
      }
    }
  }

  double cellCm_, minX_ = 0.0, minY_ = 0.0, step_ = 1.0;
  long nx_ = 0, ny_ = 0;
  std::vector<float> dist_;  // per lattice point, row-major: distance (cm while built, then cells)
};

// A candidate move in whole steps: rotation k * rotationStep, shift (i, j) * shiftStep.
struct Candidate {
  int k = 0, i = 0, j = 0;
  double approx = 0.0;  // field score: sum over occupied cells minus sum over free cells of the likelihood
  bool operator<(const Candidate& o) const { return std::tie(k, i, j) < std::tie(o.k, o.i, o.j); }
  int move() const { return std::abs(k) + std::abs(i) + std::abs(j); }
};

class Search {
 public:
  Search(const sim::Scene& scene, const sim::GridFrame& frame, int startCol, int startRow, int width, int height,
         const std::vector<KnownCell>& known, const AlignmentSearch& s)
      : scene_(scene),
        field_(scene, frame.cellCm),
        frame_(frame),
        startCol_(startCol),
        startRow_(startRow),
        width_(width),
        height_(height),
        known_(known),
        s_(s) {
    for (const KnownCell& c : known) {
      cols_.push_back(c.col);
      rows_.push_back(c.row);
      signs_.push_back(c.state == CellState::Occupied ? 1.0 : -1.0);
    }
  }
  sim::GridFrame frameOf(const Candidate& c) const {
    return movedFrame(frame_, startCol_, startRow_, c.k * s_.rotationStepDeg, c.i * s_.shiftStepCells,
                      c.j * s_.shiftStepCells);
  }
  double approx(const Candidate& c) const {
    const sim::GridFrame f = frameOf(c);
    const sim::Vec2 o = f.toPlane(sim::Vec2(0.0, 0.0));
    const sim::Vec2 u = f.toPlane(sim::Vec2(1.0, 0.0)) - o, v = f.toPlane(sim::Vec2(0.0, 1.0)) - o;
    const double ox = o.x(), oy = o.y(), ux = u.x(), uy = u.y(), vx = v.x(), vy = v.y();
    double sum = 0.0;
    for (size_t n = 0; n < cols_.size(); ++n) {
      sum += signs_[n] * field_.at(ox + cols_[n] * ux + rows_[n] * vx, oy + cols_[n] * uy + rows_[n] * vy);
    }
    return sum;
  }
  // Agreeing cells by the safe rule, counted once per candidate.
  int exact(const Candidate& c) {
    const auto it = exact_.find(c);
    if (it != exact_.end()) return it->second;
    const int agree = agreeingCells(scene_, frameOf(c), width_, height_, known_);
    exact_.emplace(c, agree);
    return agree;
  }
  bool inRange(const Candidate& c) const {
    return std::abs(c.k) <= maxK() && std::abs(c.i) <= maxS() && std::abs(c.j) <= maxS();
  }
  // Candidates on a lattice of `stride` steps: rotations k = -K..K, shifts i, j within +-shiftSteps.
  void scoreLattice(int stride, int shiftSteps, std::set<Candidate>& out) const {
    const int sMax = std::min(maxS(), shiftSteps);
    for (int k = -maxK(); k <= maxK(); k += stride) {
      for (int i = -sMax; i <= sMax; i += stride) {
        for (int j = -sMax; j <= sMax; j += stride) add({k, i, j, 0.0}, out);
      }
    }
  }
  // The candidate and its 26 neighbours one step away (within the search's range).
  void scoreAround(const Candidate& c, std::set<Candidate>& out) const {
    for (const Candidate& n : neighbours(c)) add(n, out);
  }
  std::vector<Candidate> neighbours(const Candidate& c) const {
    std::vector<Candidate> out;
    for (int dk = -1; dk <= 1; ++dk) {
      for (int di = -1; di <= 1; ++di) {
        for (int dj = -1; dj <= 1; ++dj) {
          const Candidate n{c.k + dk, c.i + di, c.j + dj, 0.0};
          if (inRange(n)) out.push_back(n);
        }
      }
    }
    return out;
  }

 private:
  int maxK() const { return static_cast<int>(std::floor(s_.maxRotationDeg / s_.rotationStepDeg + 1e-9)); }
  int maxS() const { return static_cast<int>(std::floor(s_.maxShiftCells / s_.shiftStepCells + 1e-9)); }
  void add(Candidate c, std::set<Candidate>& out) const {
    if (out.count(c) != 0) return;
    c.approx = approx(c);
    out.insert(c);
  }

  const sim::Scene& scene_;
  ObstacleField field_;
  sim::GridFrame frame_;
  int startCol_, startRow_, width_, height_;
  const std::vector<KnownCell>& known_;
  AlignmentSearch s_;
  std::vector<double> cols_, rows_, signs_;
  std::map<Candidate, int> exact_;
};

std::vector<Candidate> best(const std::set<Candidate>& all, size_t count) {
  std::vector<Candidate> v(all.begin(), all.end());
  std::stable_sort(v.begin(), v.end(), [](const Candidate& a, const Candidate& b) { return a.approx > b.approx; });
  if (v.size() > count) v.resize(count);
  return v;
}

// More agreeing cells, or as many with a smaller move.
bool better(int agree, const Candidate& c, int bestAgree, const Candidate& bestC) {
  return agree > bestAgree || (agree == bestAgree && c.move() < bestC.move());
}

}  // namespace

sim::GridFrame movedFrame(const sim::GridFrame& frame, int startCol, int startRow, double rotationDeg, double shiftCol,
                          double shiftRow) {
  const sim::Vec2 start = frame.toPlane(sim::Vec2(startCol, startRow));
  const sim::Vec2 shift = frame.toPlane(sim::Vec2(shiftCol, shiftRow)) - frame.toPlane(sim::Vec2(0.0, 0.0));
  const double rad = rotationDeg * kPi / 180.0, c = std::cos(rad), s = std::sin(rad);
  const sim::Vec2 d = frame.originCm - start;
  sim::GridFrame moved = frame;
  // Compass angles grow clockwise; with y down that is the usual (c, -s; s, c) turn (GridFrame::toPlane).
  moved.originCm = start + shift + sim::Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
  moved.headingDeg = frame.headingDeg + rotationDeg;
  return moved;
}

int agreeingCells(const sim::Scene& scene, const sim::GridFrame& frame, int width, int height,
                  const std::vector<KnownCell>& known) {
  const sim::World truth = sim::rasterizeScene(scene, frame, width, height, "aligned");
  int agree = 0;
  for (const KnownCell& c : known) {
    if (truth.blocked(c.col, c.row) == (c.state == CellState::Occupied)) ++agree;
  }
  return agree;
}

Alignment alignMap(const sim::Scene& scene, const sim::GridFrame& frame, int startCol, int startRow, int width,
                   int height, const std::vector<KnownCell>& known, const AlignmentSearch& search) {
  Search s(scene, frame, startCol, startRow, width, height, known, search);
  Candidate top{};  // the unmoved map
  int topAgree = s.exact(top);
  if (!known.empty()) {
    // Approximate: every other step over the rotations and the middle shifts (1 degree, half a cell with the
    // defaults), then one step around the best of those.
    std::set<Candidate> coarse, fine;
    s.scoreLattice(2, 2, coarse);
    for (const Candidate& c : best(coarse, 8)) s.scoreAround(c, fine);
    std::vector<std::pair<int, Candidate>> counted;  // (-agreeing, candidate): best first once sorted
    for (const Candidate& c : best(fine, static_cast<size_t>(std::max(0, search.exactCandidates)))) {
      counted.emplace_back(-s.exact(c), c);
    }
    std::sort(counted.begin(), counted.end());
    // Exact: from each of the best three, steps to the best neighbour while that improves.
    for (size_t seed = 0; seed < std::min<size_t>(3, counted.size()); ++seed) {
      Candidate at = counted[seed].second;
      int atAgree = -counted[seed].first;
      for (bool moved = true; moved;) {
        moved = false;
        for (const Candidate& n : s.neighbours(at)) {
          const int agree = s.exact(n);
          if (better(agree, n, atAgree, at)) {
            std::tie(at, atAgree) = std::make_pair(n, agree);
            moved = true;
          }
        }
      }
      if (better(atAgree, at, topAgree, top)) std::tie(top, topAgree) = std::make_pair(at, atAgree);
    }
  }
  return Alignment{top.k * search.rotationStepDeg, top.i * search.shiftStepCells, top.j * search.shiftStepCells,
                   s.frameOf(top), topAgree};
}

}  // namespace nxtmap::mapping
