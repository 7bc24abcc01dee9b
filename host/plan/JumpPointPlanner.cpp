#include "host/plan/JumpPointPlanner.hpp"

#include <algorithm>
#include <memory>

namespace nxtmap::plan {
namespace {

// A move (dc, dr), each in -1..1, as one small number: (dr + 1) * 3 + (dc + 1); kStartTag for no move.
constexpr uint8_t kStartTag = 4;
uint8_t moveTag(int dc, int dr) { return static_cast<uint8_t>((dr + 1) * 3 + (dc + 1)); }

// Jumps with block-based scans of the grid's bitsets (BitGrid), in padded coordinates (x, y).
// Every jump returns the number of steps to the jump point, or 0 when there is none.
class ScanJumper {
 public:
  ScanJumper(const Traversability& grid, MapCell goal) : b_(grid.bits()), gx_(goal.col + 1), gy_(goal.row + 1) {}

  // From (x, y), the first jump point moving straight by (dc, dr) (one of them 0).
  int straight(int x, int y, int dc, int dr) const {
    const int rw = b_.rowWords(), cw = b_.columnWords();
    if (dr == 0) {
      const uint64_t* line = b_.row(y);
      if (dc > 0) {
        const int p = BitGrid::scanUp(b_.row(y - 1), line, b_.row(y + 1), rw, x + 1);
        if (gy_ == y && gx_ > x && gx_ <= p) return gx_ - x;
        return p < rw * 64 && BitGrid::test(line, p) ? p - x : 0;
      }
      const int p = BitGrid::scanDown(b_.row(y - 1), line, b_.row(y + 1), rw, x - 1);
      if (gy_ == y && gx_ < x && gx_ >= p) return x - gx_;
      return p >= 0 && BitGrid::test(line, p) ? x - p : 0;
    }
    const uint64_t* line = b_.column(x);
    if (dr > 0) {
      const int p = BitGrid::scanUp(b_.column(x - 1), line, b_.column(x + 1), cw, y + 1);
      if (gx_ == x && gy_ > y && gy_ <= p) return gy_ - y;
      return p < cw * 64 && BitGrid::test(line, p) ? p - y : 0;
    }
    const int p = BitGrid::scanDown(b_.column(x - 1), line, b_.column(x + 1), cw, y - 1);
    if (gx_ == x && gy_ < y && gy_ >= p) return y - gy_;
    return p >= 0 && BitGrid::test(line, p) ? y - p : 0;
  }

  bool canStepDiagonal(int x, int y, int dc, int dr) const {
    return b_.open(x + dc, y + dr) && b_.open(x + dc, y) && b_.open(x, y + dr);
  }

  // From (x, y) along the legal diagonal (dc, dr): the first cell from which a straight jump along either
  // component finds a jump point (or the goal).
  int diagonal(int x, int y, int dc, int dr) const {
    for (int k = 1;; ++k) {
      if (!canStepDiagonal(x, y, dc, dr)) return 0;
      x += dc;
      y += dr;
      if (x == gx_ && y == gy_) return k;
      if (straight(x, y, dc, 0) != 0 || straight(x, y, 0, dr) != 0) return k;
    }
  }

  int jump(uint32_t /*i*/, int x, int y, int dc, int dr) const {
    return (dc != 0 && dr != 0) ? diagonal(x, y, dc, dr) : straight(x, y, dc, dr);
  }

  // Intermediate-node pruning (Harabor & Grastien 2014): walks the whole diagonal (dc, dr) from (x, y) and,
  // instead of returning each diagonal jump point d, hands over d's own successors, the jump points of the
  // straight jumps from d: emit(k, dcs, drs, m) for k diagonal steps then m straight steps by (dcs, drs)
  // (m = 0: d itself, the goal). The diagonal successor of d is the walk going on.
  template <class Emit>
  void diagonalSuccessors(uint32_t /*i*/, int x, int y, int dc, int dr, Emit&& emit) const {
    for (int k = 1;; ++k) {
      if (!canStepDiagonal(x, y, dc, dr)) return;
      x += dc;
      y += dr;
      if (x == gx_ && y == gy_) {
        emit(k, 0, 0, 0);
        return;
      }
      const int mh = straight(x, y, dc, 0);
      if (mh != 0) emit(k, dc, 0, mh);
      const int mv = straight(x, y, 0, dr);
      if (mv != 0) emit(k, 0, dr, mv);
    }
  }

 private:
  const BitGrid& b_;
  int gx_, gy_;  // the goal, padded
};

// The same jumps answered from a JumpTable, with the goal checked at query time.
class TableJumper {
 public:
  TableJumper(const Traversability& grid, const JumpTable& table, MapCell goal)
      : t_(table), s_(grid.stride()), gx_(goal.col + 1), gy_(goal.row + 1) {}

  int jump(uint32_t i, int x, int y, int dc, int dr) const {
    const int v = t_.at(i, JumpTable::direction(dc, dr));
    const int reach = v > 0 ? v : -v;  // steps that can be taken (to the jump point, or before the block)
    const int gc = gx_ - x, gr = gy_ - y;
    if (dc != 0 && dr != 0) {
      // The diagonal reaches the goal's row or column after m steps: stop there (JPS+ target jump point).
      if (gc * dc > 0 && gr * dr > 0) {
        const int m = std::min(gc * dc, gr * dr);
        if (m <= reach) return m;
      }
    } else if (dr == 0 ? (gr == 0 && gc * dc > 0 && gc * dc <= reach) : (gc == 0 && gr * dr > 0 && gr * dr <= reach)) {
      return dr == 0 ? gc * dc : gr * dr;
    }
    return v > 0 ? v : 0;
  }

  // Intermediate-node pruning as in ScanJumper::diagonalSuccessors, hopping from one diagonal jump point (or
  // target jump point) to the next by table lookups.
  template <class Emit>
  void diagonalSuccessors(uint32_t i, int x, int y, int dc, int dr, Emit&& emit) const {
    for (int walked = 0;;) {
      const int k = jump(i, x, y, dc, dr);
      if (k == 0) return;
      walked += k;
      x += k * dc;
      y += k * dr;
      i = static_cast<uint32_t>(static_cast<int>(i) + k * (dr * s_ + dc));
      if (x == gx_ && y == gy_) {
        emit(walked, 0, 0, 0);
        return;
      }
      const int mh = jump(i, x, y, dc, 0);
      if (mh != 0) emit(walked, dc, 0, mh);
      const int mv = jump(i, x, y, 0, dr);
      if (mv != 0) emit(walked, 0, dr, mv);
    }
  }

 private:
  const JumpTable& t_;
  int s_;        // stride
  int gx_, gy_;  // the goal, padded
};

int sign(int v) { return (v > 0) - (v < 0); }

// A* over jump points; Jumper::jump gives the steps to the successor in a direction (0: none).
template <class Jumper>
PlanResult jpsSearch(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options,
                     JumpScratch& scratch, const Jumper& jumper) {
  PlanResult r;
  const BitGrid& bits = grid.bits();
  const int stride = grid.stride();
  const uint32_t start = grid.index(from);
  const uint32_t goal = grid.index(to);
  const MapCell goalPadded{to.col + 1, to.row + 1};
  scratch.begin(grid.paddedSize());
  scratch.relax(start, 0.0, octile(from, to), start, kStartTag);

  int dirs[8][2];
  while (!scratch.openEmpty()) {
    const JumpScratch::Entry e = scratch.pop();
    if (scratch.closed(e.i)) continue;  // a better entry for the cell came first
    scratch.close(e.i);
    ++r.nodesExpanded;
    const double eg = scratch.g(e.i);
    if (e.i == goal) {
      r.status = PlanStatus::Found;
      r.length = eg;
      // Jump points back to the start, then each segment filled in: diagonal steps first, then straight ones
      // (a successor past a pruned intermediate node is reached diagonally, then straight).
      std::vector<MapCell> points;
      for (uint32_t i = goal;; i = scratch.parent(i)) {
        points.push_back(grid.cellOf(i));
        if (i == start) break;
      }
      std::reverse(points.begin(), points.end());
      r.path.push_back(points.front());
      for (size_t k = 1; k < points.size(); ++k) {
        for (MapCell c = points[k - 1]; c != points[k];) {
          c.col += sign(points[k].col - c.col);
          c.row += sign(points[k].row - c.row);
          r.path.push_back(c);
        }
      }
      return r;
    }
    if (options.maxNodes != 0 && r.nodesExpanded >= options.maxNodes) {
      r.status = PlanStatus::NodeLimit;
      return r;
    }

    // Directions worth trying from this jump point, given how it was reached.
    const int x = static_cast<int>(e.i % static_cast<uint32_t>(stride));
    const int y = static_cast<int>(e.i / static_cast<uint32_t>(stride));
    int n = 0;
    auto add = [&](int c, int rr) {
      dirs[n][0] = c;
      dirs[n][1] = rr;
      ++n;
    };
    const uint8_t tag = scratch.tag(e.i);
    if (tag == kStartTag) {
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if (dc != 0 || dr != 0) add(dc, dr);
        }
      }
    } else {
      const int dc = tag % 3 - 1;
      const int dr = tag / 3 - 1;
      if (dc != 0 && dr != 0) {
        add(dc, 0);
        add(0, dr);
        add(dc, dr);
      } else if (dr == 0) {
        add(dc, 0);
        for (int side : {-1, 1}) {
          if (bits.open(x, y + side) && !bits.open(x - dc, y + side)) {
            add(0, side);
            add(dc, side);
          }
        }
      } else {
        add(0, dr);
        for (int side : {-1, 1}) {
          if (bits.open(x + side, y) && !bits.open(x + side, y - dr)) {
            add(side, 0);
            add(side, dr);
          }
        }
      }
    }
    for (int k = 0; k < n; ++k) {
      const int dc = dirs[k][0], dr = dirs[k][1];
      if (dc != 0 && dr != 0) {
        jumper.diagonalSuccessors(e.i, x, y, dc, dr, [&](int steps, int sc, int sr, int m) {
          const int jx = x + steps * dc + m * sc, jy = y + steps * dr + m * sr;
          const uint32_t j = static_cast<uint32_t>(jy * stride + jx);
          if (scratch.closed(j)) return;
          // The cost of the diagonal to the pruned node, then the straight jump.
          const double g = (eg + kSqrt2 * steps) + static_cast<double>(m);
          if (g < scratch.g(j)) {
            scratch.relax(j, g, octile(MapCell{jx, jy}, goalPadded), e.i, m == 0 ? moveTag(dc, dr) : moveTag(sc, sr));
          }
        });
        continue;
      }
      const int steps = jumper.jump(e.i, x, y, dc, dr);
      if (steps == 0) continue;
      const uint32_t j = static_cast<uint32_t>(static_cast<int>(e.i) + steps * (dr * stride + dc));
      if (scratch.closed(j)) continue;
      // Exactly octile(here, j): k straight steps or k diagonal ones.
      const double g = eg + (dc != 0 && dr != 0 ? kSqrt2 * steps : static_cast<double>(steps));
      if (g < scratch.g(j)) {
        scratch.relax(j, g, octile(MapCell{x + steps * dc, y + steps * dr}, goalPadded), e.i, moveTag(dc, dr));
      }
    }
  }
  r.status = PlanStatus::NoPath;
  return r;
}

}  // namespace

PlanResult JumpPointPlanner::search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) {
  if (!precomputed_) return jpsSearch(grid, from, to, options, scratch_, ScanJumper(grid, to));
  if (!table_ || table_->gridId() != grid.id()) table_ = std::make_unique<JumpTable>(grid);
  return jpsSearch(grid, from, to, options, scratch_, TableJumper(grid, *table_, to));
}

}  // namespace nxtmap::plan
