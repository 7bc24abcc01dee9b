#include "host/sim/WorldTruth.hpp"

#include <algorithm>
#include <deque>
#include <utility>

namespace nxtmap::sim {

namespace {
constexpr int kDc[4] = {0, 1, 0, -1};
constexpr int kDr[4] = {-1, 0, 1, 0};
}  // namespace

Observability computeObservability(const World& world, int startCol, int startRow, int freeCells, int hitCells) {
  const int w = world.width();
  const int h = world.height();
  const auto index = [w](int c, int r) {
    return static_cast<size_t>(r) * static_cast<size_t>(w) + static_cast<size_t>(c);
  };
  Observability out;
  out.reachable.assign(static_cast<size_t>(w) * static_cast<size_t>(h), 0);
  out.observable.assign(out.reachable.size(), 0);

  // Breadth-first flood over free cells, 4-connected.
  std::deque<std::pair<int, int>> queue;
  if (world.inside(startCol, startRow)) {  // the robot stands there, blocked or not
    out.reachable[index(startCol, startRow)] = 1;
    queue.emplace_back(startCol, startRow);
  }
  while (!queue.empty()) {
    const auto [c, r] = queue.front();
    queue.pop_front();
    ++out.reachableCount;
    for (int d = 0; d < 4; ++d) {
      const int nc = c + kDc[d];
      const int nr = r + kDr[d];
      if (world.blocked(nc, nr) || out.reachable[index(nc, nr)]) continue;
      out.reachable[index(nc, nr)] = 1;
      queue.emplace_back(nc, nr);
    }
  }

  // Axis sight lines from every reachable cell.
  const int reach = std::max(freeCells, hitCells);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      if (!out.reachable[index(c, r)]) continue;
      for (int d = 0; d < 4; ++d) {
        for (int k = 1; k <= reach; ++k) {
          const int xc = c + k * kDc[d];
          const int xr = r + k * kDr[d];
          if (!world.inside(xc, xr)) break;
          if (world.blocked(xc, xr)) {
            if (k <= hitCells && !out.reachable[index(xc, xr)]) out.observable[index(xc, xr)] = 1;  // not the start
            break;
          }
          if (k <= freeCells) out.observable[index(xc, xr)] = 1;
        }
      }
    }
  }
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      if (!out.observable[index(c, r)]) continue;
      if (world.blocked(c, r)) {
        ++out.observableOccupied;
      } else {
        ++out.observableFree;
      }
    }
  }
  return out;
}

}  // namespace nxtmap::sim
