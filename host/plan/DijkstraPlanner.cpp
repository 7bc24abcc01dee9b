#include "host/plan/DijkstraPlanner.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace nxtmap::plan {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Runs Dijkstra from `from`; stops when `stop` is closed (if given). Fills dist and parent; counts closed cells.
void dijkstra(const Traversability& grid, MapCell from, const MapCell* stop, uint64_t maxNodes,
              std::vector<double>& dist, std::vector<uint32_t>& parent, uint64_t& closedCount, bool& limited) {
  dist.assign(grid.paddedSize(), kInf);
  parent.assign(grid.paddedSize(), 0);
  std::vector<bool> done(grid.paddedSize(), false);
  using Item = std::pair<double, uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  const uint32_t start = grid.index(from);
  dist[start] = 0.0;
  parent[start] = start;
  open.push({0.0, start});
  closedCount = 0;
  limited = false;
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (done[i]) continue;
    done[i] = true;
    ++closedCount;
    const MapCell c = grid.cellOf(i);
    if (stop && c == *stop) return;
    if (maxNodes != 0 && closedCount >= maxNodes) {
      limited = true;
      return;
    }
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if ((dc == 0 && dr == 0) || !grid.canStep(c, dc, dr)) continue;
        const uint32_t n = grid.index(MapCell{c.col + dc, c.row + dr});
        const double nd = d + ((dc != 0 && dr != 0) ? kSqrt2 : 1.0);
        if (nd < dist[n]) {
          dist[n] = nd;
          parent[n] = i;
          open.push({nd, n});
        }
      }
    }
  }
}

}  // namespace

PlanResult DijkstraPlanner::search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) {
  std::vector<double> dist;
  std::vector<uint32_t> parent;
  PlanResult r;
  bool limited = false;
  dijkstra(grid, from, &to, options.maxNodes, dist, parent, r.nodesExpanded, limited);
  const uint32_t goal = grid.index(to);
  if (limited) {  // stopped before the goal was closed
    r.status = PlanStatus::NodeLimit;
    return r;
  }
  if (dist[goal] == kInf) {
    r.status = PlanStatus::NoPath;
    return r;
  }
  r.status = PlanStatus::Found;
  r.length = dist[goal];
  const uint32_t start = grid.index(from);
  for (uint32_t i = goal;; i = parent[i]) {
    r.path.push_back(grid.cellOf(i));
    if (i == start) break;
  }
  std::reverse(r.path.begin(), r.path.end());
  return r;
}

std::vector<double> distancesFrom(const Traversability& grid, MapCell from) {
  std::vector<double> dist;
  std::vector<uint32_t> parent;
  uint64_t closed = 0;
  bool limited = false;
  dijkstra(grid, from, nullptr, 0, dist, parent, closed, limited);
  return dist;
}

}  // namespace nxtmap::plan
