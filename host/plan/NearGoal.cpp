#include "host/plan/NearGoal.hpp"

#include <limits>

#include "host/plan/DijkstraPlanner.hpp"

namespace nxtmap::plan {

std::optional<MapCell> nearestCellNextTo(const Traversability& grid, MapCell from, const mapio::CellBlock& block) {
  if (!grid.passable(from)) return std::nullopt;
  const std::vector<double> dist = distancesFrom(grid, from);
  std::optional<MapCell> best;
  double bestDist = std::numeric_limits<double>::infinity();
  for (int r = block.row - 1; r <= block.row + block.height; ++r) {
    for (int c = block.col - 1; c <= block.col + block.width; ++c) {
      const MapCell cell{c, r};
      if (block.contains(c, r) || !grid.passable(cell)) continue;
      const double d = dist[grid.index(cell)];
      if (d < bestDist) {  // rows then cols ascending: the first of equal distances wins
        bestDist = d;
        best = cell;
      }
    }
  }
  return best;
}

}  // namespace nxtmap::plan
