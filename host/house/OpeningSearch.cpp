#include "host/house/OpeningSearch.hpp"

#include <algorithm>
#include <cstdlib>

namespace nxtmap::house {
namespace {

// Free cell `c` (room frame) faces unknown space along d (house frame) for `depth` cells.
bool facesUnknown(const network::RoomNode& room, const network::RoomMap& known, Cell c, Dir houseDir, int depth) {
  if (!room.map.isFree(c)) return false;
  const Cell h = room.toHouse.apply(c);
  for (int k = 1; k <= depth; ++k) {
    if (known.at(advance(h, houseDir, static_cast<int16_t>(k))) != CellState::Unknown) return false;
  }
  return true;
}

}  // namespace

std::optional<Opening> findOpening(const network::HouseNetwork& network, const network::RoomMap& known,
                                   const std::vector<Cell>& tried, const OpeningLimits& limits) {
  std::optional<Opening> best;
  const auto& rooms = network.rooms();
  for (size_t r = 0; r < rooms.size(); ++r) {
    const network::RoomNode& room = rooms[r];
    const network::RoomMap& m = room.map;
    for (int d = 0; d < 4; ++d) {
      const Dir roomDir = static_cast<Dir>(d);
      const Dir houseDir = room.toHouse.apply(roomDir);
      const Dir along = rotate(roomDir, 1);
      for (int y = m.minY(); y <= m.maxY(); ++y) {
        for (int x = m.minX(); x <= m.maxX(); ++x) {
          const Cell start{static_cast<int16_t>(x), static_cast<int16_t>(y)};
          // Only from the first cell of a run (its predecessor along the run does not qualify).
          if (!facesUnknown(room, known, start, houseDir, limits.depth) ||
              facesUnknown(room, known, advance(start, along, -1), houseDir, limits.depth))
            continue;
          int width = 1;
          while (facesUnknown(room, known, advance(start, along, static_cast<int16_t>(width)), houseDir, limits.depth))
            ++width;
          if (width < limits.minWidth || (best && static_cast<int>(best->cells.size()) >= width)) continue;
          const Cell inside = advance(start, along, static_cast<int16_t>(width / 2));
          const Cell insideHouse = room.toHouse.apply(inside);
          bool done = false;
          for (const Cell t : tried)
            done = done || (std::abs(t.x - insideHouse.x) + std::abs(t.y - insideHouse.y) <= 2);
          if (done) continue;
          Opening o;
          o.room = static_cast<int>(r);
          o.inside = inside;
          o.outward = roomDir;
          const int kept = std::min(width, limits.maxWidth), first = width / 2 - kept / 2;
          for (int i = first; i < first + kept; ++i)
            o.cells.push_back(advance(advance(start, along, static_cast<int16_t>(i)), roomDir));
          best = o;
        }
      }
    }
  }
  return best;
}

}  // namespace nxtmap::house
