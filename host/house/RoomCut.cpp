#include "host/house/RoomCut.hpp"

#include <algorithm>
#include <deque>

#include "common/grid/PackedCells.hpp"
#include "common/grid/RoomGrid.hpp"

namespace nxtmap::house {

namespace {

size_t indexIn(const network::RoomMap& m, Cell c) {
  return static_cast<size_t>((c.y - m.minY()) * m.width() + (c.x - m.minX()));
}

bool isDoor(const std::vector<Cell>& doors, Cell c) { return std::find(doors.begin(), doors.end(), c) != doors.end(); }

// 1 for every cell of `full` reached from the seeds through free cells (four-connected) without entering a door.
// The start cell always counts (the robot stood there), whatever noise later said about it; so does every other
// cell the robot stood in that the map holds free: a wall mapped from a pose gone astray may cut the start off
// from the room the robot went on to map.
std::vector<uint8_t> reachedCells(const network::RoomMap& full, const std::vector<Cell>& doors,
                                  const std::vector<Cell>& stood) {
  std::vector<uint8_t> reached(static_cast<size_t>(full.width()) * static_cast<size_t>(full.height()), 0);
  std::deque<Cell> queue;
  const auto reach = [&](Cell c) {
    reached[indexIn(full, c)] = 1;
    queue.push_back(c);
  };
  const Cell start{0, 0};
  if (full.inside(start)) reach(start);
  for (const Cell c : stood) {
    if (full.isFree(c) && !isDoor(doors, c) && reached[indexIn(full, c)] == 0) reach(c);
  }
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (int d = 0; d < 4; ++d) {
      const Cell n = advance(c, static_cast<Dir>(d));
      if (full.isFree(n) && reached[indexIn(full, n)] == 0 && !isDoor(doors, n)) reach(n);
    }
  }
  return reached;
}

}  // namespace

network::RoomMap cutToRoom(const network::RoomMap& full, const std::vector<Cell>& doors,
                           const std::vector<Cell>& stood) {
  const std::vector<uint8_t> reached = reachedCells(full, doors, stood);
  const auto wasReached = [&](Cell c) { return full.inside(c) && reached[indexIn(full, c)] != 0; };
  network::RoomMap cut(full.minX(), full.minY(), full.width(), full.height());
  for (int y = full.minY(); y <= full.maxY(); ++y) {
    for (int x = full.minX(); x <= full.maxX(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      bool keep = wasReached(c) || isDoor(doors, c);
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
