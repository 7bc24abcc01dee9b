#include "host/house/StandingScan.hpp"

#include <climits>
#include <cstdlib>

namespace nxtmap::house {

int standingScore(const network::RoomMap& known, Cell at, const std::vector<StandingReading>& readings,
                  const RangeGeometry& geometry, int reachCm, const Dir* blocked) {
  if (known.at(at) == CellState::Occupied) return INT_MIN / 2;
  RangeGeometry reach = geometry;
  reach.maxCm = static_cast<int16_t>(reachCm);
  const int reachCells = reach.hitCells();
  int score = 0;
  for (const StandingReading& r : readings) {
    // The first known wall along the beam (1 = the adjacent cell), 0 when none within reach + 1.
    const int wall = known.firstOccupied(at, r.dir, reachCells + 1);
    if (r.echo) {
      const int hit = geometry.hitCell(static_cast<int16_t>(r.cm));
      if (wall == hit) {
        score += 2;
      } else if (wall != 0 && std::abs(wall - hit) == 1) {
        score += 1;
      } else if (wall != 0 && wall < hit) {
        score -= 2;
      }
    } else if (wall != 0 && wall < reachCells) {
      score -= 2;
    }
  }
  if (blocked != nullptr && known.isFree(advance(at, *blocked))) score -= 2;
  return score;
}

Cell bestStandingShift(const network::RoomMap& known, Cell believed, const std::vector<StandingReading>& readings,
                       const RangeGeometry& geometry, int reachCm, const Dir* blocked, int maxShift, int margin) {
  const int here = standingScore(known, believed, readings, geometry, reachCm, blocked);
  Cell best{0, 0};
  int bestScore = here;
  int bestSize = 0;
  for (int dy = -maxShift; dy <= maxShift; ++dy) {
    for (int dx = -maxShift; dx <= maxShift; ++dx) {
      const Cell at{static_cast<int16_t>(believed.x + dx), static_cast<int16_t>(believed.y + dy)};
      if ((dx == 0 && dy == 0) || !known.isFree(at)) continue;
      const int s = standingScore(known, at, readings, geometry, reachCm, blocked);
      const int size = std::abs(dx) + std::abs(dy);
      if (s > bestScore || (s == bestScore && size < bestSize)) {
        best = Cell{static_cast<int16_t>(dx), static_cast<int16_t>(dy)};
        bestScore = s;
        bestSize = size;
      }
    }
  }
  if (bestScore - here < margin) return Cell{0, 0};
  return best;
}

}  // namespace nxtmap::house
