#include "host/plan/AStarPlanner.hpp"

#include <algorithm>

namespace nxtmap::plan {

PlanResult AStarPlanner::search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) {
  PlanResult r;
  const int s = grid.stride();
  const int dcs[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  const int drs[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  int offset[8];
  for (int d = 0; d < 8; ++d) offset[d] = drs[d] * s + dcs[d];

  scratch_.begin(grid.paddedSize());
  const uint32_t start = grid.index(from);
  const uint32_t goal = grid.index(to);
  scratch_.relax(start, 0.0, octile(from, to), start);
  while (!scratch_.openEmpty()) {
    const SearchScratch::Entry e = scratch_.pop();
    if (scratch_.closed(e.i) || e.g > scratch_.g(e.i)) continue;  // stale entry
    scratch_.close(e.i);
    ++r.nodesExpanded;
    if (e.i == goal) {
      r.status = PlanStatus::Found;
      r.length = e.g;
      for (uint32_t i = goal;; i = scratch_.parent(i)) {
        r.path.push_back(grid.cellOf(i));
        if (i == start) break;
      }
      std::reverse(r.path.begin(), r.path.end());
      return r;
    }
    if (options.maxNodes != 0 && r.nodesExpanded >= options.maxNodes) {
      r.status = PlanStatus::NodeLimit;
      return r;
    }
    for (int d = 0; d < 8; ++d) {
      const uint32_t n = static_cast<uint32_t>(static_cast<int>(e.i) + offset[d]);
      if (!grid.open(n) || scratch_.closed(n)) continue;
      const bool diagonal = d >= 4;
      if (diagonal && (!grid.open(static_cast<uint32_t>(static_cast<int>(e.i) + dcs[d])) ||
                       !grid.open(static_cast<uint32_t>(static_cast<int>(e.i) + drs[d] * s)))) {
        continue;
      }
      const double g = e.g + (diagonal ? kSqrt2 : 1.0);
      if (g < scratch_.g(n)) scratch_.relax(n, g, octile(grid.cellOf(n), to), e.i);
    }
  }
  r.status = PlanStatus::NoPath;
  return r;
}

}  // namespace nxtmap::plan
