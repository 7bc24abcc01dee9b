#include "host/mapping/MapScore.hpp"

namespace nxtmap::mapping {

MapScore scoreRun(const MappingRun& run) {
  const sim::World& world = run.world();
  const RangeGeometry& g = run.explorerConfig().geometry;
  const sim::Observability obs = sim::computeObservability(world, run.config().startCol, run.config().startRow,
                                                           g.freeCells(), g.hitCells());
  MapScore s;
  for (int row = 0; row < world.height(); ++row) {
    for (int col = 0; col < world.width(); ++col) {
      const bool blocked = world.blocked(col, row);
      const bool observable = obs.observable[static_cast<size_t>(row * world.width() + col)] != 0;
      const CellState b = run.belief(col, row);
      (blocked ? s.actualOccupied : s.actualFree)++;
      if (observable) (blocked ? s.observableOccupied : s.observableFree)++;
      switch (b) {
        case CellState::Unknown:
          ++s.unknown;
          if (observable) ++s.unknownObservable;
          break;
        case CellState::Free:
          ++s.foundFree;
          if (blocked) ++s.wrongCells;
          break;
        case CellState::Occupied:
          ++s.foundOccupied;
          if (!blocked) ++s.wrongCells;
          if (blocked && observable) ++s.detectedOccupied;
          break;
      }
    }
  }
  // Cells the robot believes it knows outside the world map: free ones are wrong.
  const Bounds w = run.explorer().map().grid().window();
  for (int16_t y = w.minY; y <= w.maxY; ++y) {
    for (int16_t x = w.minX; x <= w.maxX; ++x) {
      int col, row;
      run.frame().toWorld(Cell{x, y}, col, row);
      if (world.inside(col, row)) continue;
      if (run.explorer().map().at(Cell{x, y}) == CellState::Free) ++s.wrongCells;
    }
  }
  return s;
}

}  // namespace nxtmap::mapping
