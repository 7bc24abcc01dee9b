#include "host/plan/JumpPointPlanner.hpp"

#include <algorithm>

namespace nxtmap::plan {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

// Jumps over the padded grid; indices step by `dc + dr * stride`.
class Jumper {
 public:
  Jumper(const Traversability& grid, uint32_t goal) : g_(grid), s_(grid.stride()), goal_(goal) {}

  bool open(uint32_t i, int dc, int dr) const { return g_.open(at(i, dc, dr)); }
  uint32_t at(uint32_t i, int dc, int dr) const {
    return static_cast<uint32_t>(static_cast<int>(i) + dr * s_ + dc);
  }
  bool canStep(uint32_t i, int dc, int dr) const {
    return open(i, dc, dr) && (dc == 0 || dr == 0 || (open(i, dc, 0) && open(i, 0, dr)));
  }

  // From the cell before i, moving straight by (dc, dr): the first jump point at or after i, or kNone.
  uint32_t straight(uint32_t i, int dc, int dr) const {
    for (;; i = at(i, dc, dr)) {
      if (!g_.open(i)) return kNone;
      if (i == goal_) return i;
      if (dr == 0) {
        if ((open(i, 0, -1) && !open(i, -dc, -1)) || (open(i, 0, 1) && !open(i, -dc, 1))) return i;
      } else {
        if ((open(i, -1, 0) && !open(i, -1, -dr)) || (open(i, 1, 0) && !open(i, 1, -dr))) return i;
      }
    }
  }

  // From the cell before i, having made a legal diagonal move (dc, dr) onto i: the first jump point, or kNone.
  uint32_t diagonal(uint32_t i, int dc, int dr) const {
    for (;;) {
      if (i == goal_) return i;
      if (straight(at(i, dc, 0), dc, 0) != kNone || straight(at(i, 0, dr), 0, dr) != kNone) return i;
      if (!canStep(i, dc, dr)) return kNone;
      i = at(i, dc, dr);
    }
  }

 private:
  const Traversability& g_;
  int s_;
  uint32_t goal_;
};

int sign(int v) { return (v > 0) - (v < 0); }

}  // namespace

PlanResult JumpPointPlanner::search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) {
  PlanResult r;
  const uint32_t start = grid.index(from);
  const uint32_t goal = grid.index(to);
  const Jumper jump(grid, goal);
  scratch_.begin(grid.paddedSize());
  scratch_.relax(start, 0.0, octile(from, to), start);

  int dirs[8][2];
  while (!scratch_.openEmpty()) {
    const SearchScratch::Entry e = scratch_.pop();
    if (scratch_.closed(e.i) || e.g > scratch_.g(e.i)) continue;
    scratch_.close(e.i);
    ++r.nodesExpanded;
    if (e.i == goal) {
      r.status = PlanStatus::Found;
      r.length = e.g;
      // Jump points back to the start, then each straight or diagonal segment filled in.
      std::vector<MapCell> points;
      for (uint32_t i = goal;; i = scratch_.parent(i)) {
        points.push_back(grid.cellOf(i));
        if (i == start) break;
      }
      std::reverse(points.begin(), points.end());
      r.path.push_back(points.front());
      for (size_t k = 1; k < points.size(); ++k) {
        const int dc = sign(points[k].col - points[k - 1].col);
        const int dr = sign(points[k].row - points[k - 1].row);
        for (MapCell c = points[k - 1]; c != points[k];) {
          c.col += dc;
          c.row += dr;
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
    const MapCell here = grid.cellOf(e.i);
    int n = 0;
    if (e.i == start) {
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if (dc != 0 || dr != 0) {
            dirs[n][0] = dc;
            dirs[n][1] = dr;
            ++n;
          }
        }
      }
    } else {
      const MapCell p = grid.cellOf(scratch_.parent(e.i));
      const int dc = sign(here.col - p.col);
      const int dr = sign(here.row - p.row);
      auto add = [&](int c, int rr) {
        dirs[n][0] = c;
        dirs[n][1] = rr;
        ++n;
      };
      if (dc != 0 && dr != 0) {
        add(dc, 0);
        add(0, dr);
        add(dc, dr);
      } else if (dr == 0) {
        add(dc, 0);
        for (int side : {-1, 1}) {
          if (jump.open(e.i, 0, side) && !jump.open(e.i, -dc, side)) {
            add(0, side);
            add(dc, side);
          }
        }
      } else {
        add(0, dr);
        for (int side : {-1, 1}) {
          if (jump.open(e.i, side, 0) && !jump.open(e.i, side, -dr)) {
            add(side, 0);
            add(side, dr);
          }
        }
      }
    }
    for (int k = 0; k < n; ++k) {
      const int dc = dirs[k][0];
      const int dr = dirs[k][1];
      if (!jump.canStep(e.i, dc, dr)) continue;
      const uint32_t next = jump.at(e.i, dc, dr);
      const uint32_t j = (dc != 0 && dr != 0) ? jump.diagonal(next, dc, dr) : jump.straight(next, dc, dr);
      if (j == kNone || scratch_.closed(j)) continue;
      const MapCell jc = grid.cellOf(j);
      const double g = e.g + octile(here, jc);
      if (g < scratch_.g(j)) scratch_.relax(j, g, octile(jc, to), e.i);
    }
  }
  r.status = PlanStatus::NoPath;
  return r;
}

}  // namespace nxtmap::plan
