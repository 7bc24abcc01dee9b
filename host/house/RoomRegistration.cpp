#include "host/house/RoomRegistration.hpp"

namespace nxtmap::house {
namespace {
// Agreement of `fresh` (placed by toHouse, then shifted) with `known` on the cells both know:
// an occupied cell both hold +3, a free cell both hold +1, a disagreement -6 (and counted): one map
// holding free what the other holds occupied is strong evidence against the shift.
struct Fit {
  int score = 0;
  int conflicts = 0;  // cells one map holds free and the other occupied
};

Fit agreement(const network::RoomMap& fresh, const network::RoomTransform& toHouse, const network::RoomMap& known,
              int dx, int dy) {
  Fit f;
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
      if (a != b) {
        f.score -= 6;
        ++f.conflicts;
      } else {
        f.score += a == CellState::Occupied ? 3 : 1;
      }
    }
  }
  return f;
}
}  // namespace

RoomRegistration registerRoom(const network::RoomMap& fresh, const network::RoomTransform& toHouse,
                              const network::RoomMap& known, int maxShift, int margin, int resolved) {
  RoomRegistration r;
  r.toHouse = toHouse;
  const Fit put = agreement(fresh, toHouse, known, 0, 0);
  r.scoreBefore = r.scoreAfter = put.score;
  Fit best = put;
  int bx = 0, by = 0;
  for (int dy = -maxShift; dy <= maxShift; ++dy) {
    for (int dx = -maxShift; dx <= maxShift; ++dx) {
      if (dx == 0 && dy == 0) continue;
      const Fit f = agreement(fresh, toHouse, known, dx, dy);
      if (f.score > best.score) {
        best = f;
        bx = dx;
        by = dy;
      }
    }
  }
  if (best.score < put.score + margin || put.conflicts - best.conflicts < resolved) return r;
  r.dx = bx;
  r.dy = by;
  r.scoreAfter = best.score;
  r.toHouse = network::RoomTransform::fromParts(toHouse.x() + bx, toHouse.y() + by, toHouse.quarterTurns());
  return r;
}

}  // namespace nxtmap::house
