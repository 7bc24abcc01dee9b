#include "host/house/RoomRegistration.hpp"

namespace nxtmap::house {
namespace {
// Agreement of `fresh` (placed by toHouse, then shifted) with `known` on the cells both know:
// an occupied cell both hold +3, a free cell both hold +1, a disagreement -2.
int agreement(const network::RoomMap& fresh, const network::RoomTransform& toHouse, const network::RoomMap& known,
              int dx, int dy) {
  int s = 0;
  for (int y = fresh.minY(); y <= fresh.maxY(); ++y) {
    for (int x = fresh.minX(); x <= fresh.maxX(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      const CellState a = fresh.at(c);
      if (a == CellState::Unknown) continue;
      Cell h = toHouse.apply(c);
      h.x = static_cast<int16_t>(h.x + dx);
      h.y = static_cast<int16_t>(h.y + dy);
      const CellState b = known.at(h);
      if (b == CellState::Unknown) continue;
      s += a == b ? (a == CellState::Occupied ? 3 : 1) : -2;
    }
  }
  return s;
}
}  // namespace

RoomRegistration registerRoom(const network::RoomMap& fresh, const network::RoomTransform& toHouse,
                              const network::RoomMap& known, int maxShift, int margin) {
  RoomRegistration r;
  r.toHouse = toHouse;
  r.scoreBefore = r.scoreAfter = agreement(fresh, toHouse, known, 0, 0);
  int best = r.scoreBefore, bx = 0, by = 0;
  for (int dy = -maxShift; dy <= maxShift; ++dy) {
    for (int dx = -maxShift; dx <= maxShift; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const int s = agreement(fresh, toHouse, known, dx, dy);
      if (s > best) {
        best = s;
        bx = dx;
        by = dy;
      }
    }
  }
  if (best < r.scoreBefore + margin) return r;
  r.dx = bx;
  r.dy = by;
  r.scoreAfter = best;
  r.toHouse = network::RoomTransform::fromParts(toHouse.x() + bx, toHouse.y() + by, toHouse.quarterTurns());
  return r;
}

}  // namespace nxtmap::house
