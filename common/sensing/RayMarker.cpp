#include "common/sensing/RayMarker.hpp"

namespace nxtmap {

RayMarkResult markRay(MapLayers& map, const RangeGeometry& geometry, Cell from, Dir d, const RangeReading& reading,
                      bool trustBlind) {
  RayMarkResult result;
  int16_t freeUpTo = 0;  // last cell (1 = adjacent) to observe as free
  int16_t hitAt = 0;     // cell to observe as occupied, 0 = none
  switch (reading.status) {
    case RangeStatus::Good:
      hitAt = geometry.hitCell(reading.cm);
      freeUpTo = static_cast<int16_t>(hitAt - 1);
      if (!geometry.sureHit(reading.cm)) hitAt = 0;  // may come from beside the axis
      break;
    case RangeStatus::TooNear: hitAt = 1; break;
    case RangeStatus::NoEcho:
      for (int16_t k = 1; k <= geometry.blindCells(); ++k) {
        if (!trustBlind && map.at(advance(from, d, k)) != CellState::Free) {
          result.conclusive = true;  // read, and nothing can be concluded from it
          return result;
        }
      }
      freeUpTo = geometry.freeCells();
      break;
    case RangeStatus::TooFar: freeUpTo = geometry.freeCells(); break;
    case RangeStatus::Inconsistent: return result;
  }
  result.conclusive = true;
  for (int16_t k = 1; k <= freeUpTo; ++k) {
    const Cell c = advance(from, d, k);
    const bool wall = map.at(c) == CellState::Occupied;
    if (!map.observeFree(c)) {
      result.clipped = true;
      return result;
    }
    ++result.cellsMarked;
    if (wall) return result;
  }
  if (hitAt > 0) {
    if (!map.observeOccupied(advance(from, d, hitAt))) {
      result.clipped = true;
      return result;
    }
    ++result.cellsMarked;
  }
  return result;
}

}  // namespace nxtmap
