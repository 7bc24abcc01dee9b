#include "host/house/RoomCut.hpp"

#include <algorithm>
#include <deque>

#include "common/grid/PackedCells.hpp"
#include "common/grid/RoomGrid.hpp"

namespace nxtmap::house {

network::RoomMap cutToRoom(const network::RoomMap& full, const std::vector<Cell>& doors) {
  const auto isDoor = [&](Cell c) { return std::find(doors.begin(), doors.end(), c) != doors.end(); };
  const auto idx = [&](Cell c) {
    return static_cast<size_t>((c.y - full.minY()) * full.width() + (c.x - full.minX()));
  };
  std::vector<uint8_t> reached(static_cast<size_t>(full.width()) * static_cast<size_t>(full.height()), 0);
  // The start cell always counts (the robot stood there), whatever noise later said about it.
  const Cell start{0, 0};
  if (full.inside(start)) {
    std::deque<Cell> queue{start};
    reached[idx(start)] = 1;
    while (!queue.empty()) {
      const Cell c = queue.front();
      queue.pop_front();
      for (int d = 0; d < 4; ++d) {
        const Cell n = advance(c, static_cast<Dir>(d));
        if (!full.isFree(n) || reached[idx(n)] || isDoor(n)) continue;
        reached[idx(n)] = 1;
        queue.push_back(n);
      }
    }
  }
  const auto wasReached = [&](Cell c) { return full.inside(c) && reached[idx(c)] != 0; };
  network::RoomMap cut(full.minX(), full.minY(), full.width(), full.height());
  for (int y = full.minY(); y <= full.maxY(); ++y) {
    for (int x = full.minX(); x <= full.maxX(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      bool keep = wasReached(c) || isDoor(c);
      for (int dy = -1; dy <= 1 && !keep; ++dy) {
        for (int dx = -1; dx <= 1 && !keep; ++dx) keep = wasReached(offset(c, dx, dy));
      }
      if (keep) cut.set(c, full.at(c));
    }
  }
  return cut;
}

RoomInterpretation interpretMap(const network::RoomMap& map, const RoomLimits& room, const DoorwayLimits& doorways) {
  int16_t side = 16;
  while (side < map.width() || side < map.height()) side = static_cast<int16_t>(side * 2);
  std::vector<uint8_t> storage(packedBytes(side, side, 2));
  RoomGrid grid(storage.data(), side, side);
  for (int y = map.minY(); y <= map.maxY(); ++y) {
    for (int x = map.minX(); x <= map.maxX(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      if (map.at(c) != CellState::Unknown) (void)grid.set(c, map.at(c));
    }
  }
  return interpretRoom(grid, room, doorways);
}

}  // namespace nxtmap::house
