#include "host/house/StartAnchor.hpp"

#include <cstdlib>

namespace nxtmap::house {
namespace {
// Whether every reading along the vertical or horizontal axis fits the map seen from `at`: the
// nearest wall face in the beam, which beyond wideFromMm takes in the lanes on either side too.
bool fits(const network::RoomMap& map, Cell at, const std::vector<AnchorReading>& readings, bool vertical,
          const AnchorGeometry& g) {
  for (const AnchorReading& r : readings) {
    if (isVertical(r.dir) != vertical) continue;
    int wall = map.firstOccupied(at, r.dir, g.reachCells);
    if (r.mm > g.wideFromMm) {
      for (int side = -1; side <= 1; side += 2) {
        const int k = map.firstOccupied(advance(at, rotate(r.dir, side)), r.dir, g.reachCells);
        if (k != 0 && (wall == 0 || k < wall)) wall = k;
      }
    }
    if (wall == 0 || std::abs(r.mm - (2 * wall - 1) * g.cellMm / 2) > g.toleranceMm) return false;
  }
  return true;
}

// The shift along one axis (0: none found, or none needed, or not a single one).
int axisShift(const network::RoomMap& map, Cell start, const std::vector<AnchorReading>& readings, bool vertical,
              const AnchorGeometry& g) {
  bool any = false;
  for (const AnchorReading& r : readings) any = any || isVertical(r.dir) == vertical;
  if (!any || fits(map, start, readings, vertical, g)) return 0;
  int found = 0, count = 0;
  for (int s = -g.maxShift; s <= g.maxShift; ++s) {
    if (s == 0) continue;
    const Cell at =
        vertical ? Cell{start.x, static_cast<int16_t>(start.y + s)} : Cell{static_cast<int16_t>(start.x + s), start.y};
    if (map.isFree(at) && fits(map, at, readings, vertical, g)) {
      found = s;
      ++count;
    }
  }
  return count == 1 ? found : 0;
}
}  // namespace

Cell startAnchorShift(const network::RoomMap& map, Cell start, const std::vector<AnchorReading>& readings,
                      const AnchorGeometry& geometry) {
  const int dx = axisShift(map, start, readings, false, geometry);
  const int dy = axisShift(map, start, readings, true, geometry);
  const Cell shift{static_cast<int16_t>(dx), static_cast<int16_t>(dy)};
  const Cell at{static_cast<int16_t>(start.x + dx), static_cast<int16_t>(start.y + dy)};
  if ((dx != 0 || dy != 0) && !map.isFree(at)) return Cell{0, 0};
  return shift;
}

}  // namespace nxtmap::house
