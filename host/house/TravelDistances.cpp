#include "host/house/TravelDistances.hpp"

#include <cstddef>
#include <deque>

namespace nxtmap::house {

std::vector<int> travelDistances(const network::RoomMap& known, Cell from) {
  std::vector<int> dist(static_cast<size_t>(known.width()) * static_cast<size_t>(known.height()), -1);
  const auto idx = [&](Cell c) {
    return static_cast<size_t>((c.y - known.minY()) * known.width() + (c.x - known.minX()));
  };
  if (!known.inside(from)) return dist;
  std::deque<Cell> queue{from};
  dist[idx(from)] = 0;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (int d = 0; d < 4; ++d) {
      const Cell n = advance(c, static_cast<Dir>(d));
      if (!known.isFree(n) || dist[idx(n)] >= 0) continue;
      dist[idx(n)] = dist[idx(c)] + 1;
      queue.push_back(n);
    }
  }
  return dist;
}

}  // namespace nxtmap::house
