#include "host/mapping/MapScore.hpp"

#include "host/sim/TruthRaster.hpp"

namespace nxtmap::mapping {

namespace {

// The map's cells on the truth's grid: Unknown where it holds nothing.
std::vector<CellState> beliefOnGrid(const sim::World& truth, const std::vector<KnownCell>& known) {
  std::vector<CellState> cells(static_cast<size_t>(truth.width()) * static_cast<size_t>(truth.height()),
                               CellState::Unknown);
  for (const KnownCell& k : known) {
    if (truth.inside(k.col, k.row)) cells[static_cast<size_t>(k.row * truth.width() + k.col)] = k.state;
  }
  return cells;
}

// The start-frame figures of `known` against `truth` (observability from the start cell).
MapScore countAgainst(const sim::World& truth, int startCol, int startRow, int freeCells, int hitCells,
                      const std::vector<KnownCell>& known) {
  const sim::Observability obs = sim::computeObservability(truth, startCol, startRow, freeCells, hitCells);
  const std::vector<CellState> belief = beliefOnGrid(truth, known);
  MapScore s;
  for (int row = 0; row < truth.height(); ++row) {
    for (int col = 0; col < truth.width(); ++col) {
      const size_t at = static_cast<size_t>(row * truth.width() + col);
      const bool blocked = truth.blocked(col, row);
      const bool observable = obs.observable[at] != 0;
      (blocked ? s.actualOccupied : s.actualFree)++;
      if (observable) (blocked ? s.observableOccupied : s.observableFree)++;
      switch (belief[at]) {
        case CellState::Unknown:
          ++s.unknown;
          if (observable) ++s.unknownObservable;
          break;
        case CellState::Free:
          ++s.foundFree;
          if (blocked) ++s.unsafeFree;
          break;
        case CellState::Occupied:
          ++s.foundOccupied;
          if (!blocked) ++s.phantomOccupied;
          if (blocked && observable) ++s.detectedOccupied;
          break;
      }
    }
  }
  // Cells the robot believes it knows outside the world map: outside is solid, so free ones are wrong.
  for (const KnownCell& k : known) {
    if (!truth.inside(k.col, k.row) && k.state == CellState::Free) ++s.unsafeFree;
  }
  s.wrongCells = s.unsafeFree + s.phantomOccupied;
  return s;
}

bool isLost(const sim::GridFrame& frame, const ScoreInput& in) {
  int col = 0, row = 0;
  frame.cellOf(in.trueCentreCm, col, row);
  return col != in.believedCol || row != in.believedRow;
}

void fillAligned(MapScore& s, const MapScore& a, const Alignment& how, bool lost) {
  s.alignRotationDeg = how.rotationDeg;
  s.alignShiftCol = how.shiftCol;
  s.alignShiftRow = how.shiftRow;
  s.observableOccupiedAligned = a.observableOccupied;
  s.detectedOccupiedAligned = a.detectedOccupied;
  s.wrongCellsAligned = a.wrongCells;
  s.unsafeFreeAligned = a.unsafeFree;
  s.phantomOccupiedAligned = a.phantomOccupied;
  s.lostAligned = lost;
}

}  // namespace

MapScore scoreMap(const ScoreInput& in) {
  const sim::World& truth = *in.truth;
  MapScore s = countAgainst(truth, in.startCol, in.startRow, in.freeCells, in.hitCells, in.known);
  s.lost = isLost(in.frame, in);
  fillAligned(s, s, Alignment{0.0, 0.0, 0.0, in.frame, 0}, s.lost);
  if (in.scene == nullptr) return s;
  const Alignment how =
      alignMap(*in.scene, in.frame, in.startCol, in.startRow, truth.width(), truth.height(), in.known);
  if (how.rotationDeg == 0.0 && how.shiftCol == 0.0 && how.shiftRow == 0.0) return s;
  const sim::World moved = sim::rasterizeScene(*in.scene, how.frame, truth.width(), truth.height(), truth.name());
  // Observability from the cell that holds the true start point on the moved grid (the start cell if blocked).
  int col = in.startCol, row = in.startRow;
  how.frame.cellOf(in.frame.toPlane(sim::Vec2(in.startCol, in.startRow)), col, row);
  if (moved.blocked(col, row)) {
    col = in.startCol;
    row = in.startRow;
  }
  fillAligned(s, countAgainst(moved, col, row, in.freeCells, in.hitCells, in.known), how, isLost(how.frame, in));
  return s;
}

MapScore scoreRun(const MappingRun& run) {
  ScoreInput in;
  in.scene = &run.robot().scene();
  in.truth = &run.world();
  in.frame = run.robot().frame();
  in.startCol = run.config().startCol;
  in.startRow = run.config().startRow;
  in.freeCells = run.explorerConfig().geometry.freeCells();
  in.hitCells = run.explorerConfig().geometry.hitCells();
  const Bounds w = run.explorer().map().grid().window();
  for (int16_t y = w.minY; y <= w.maxY; ++y) {
    for (int16_t x = w.minX; x <= w.maxX; ++x) {
      const CellState state = run.explorer().map().at(Cell{x, y});
      if (state == CellState::Unknown) continue;
      KnownCell k;
      k.state = state;
      run.frame().toWorld(Cell{x, y}, k.col, k.row);
      in.known.push_back(k);
    }
  }
  run.believedCell(in.believedCol, in.believedRow);
  in.trueCentreCm = sim::Vec2(run.robot().xCm(), run.robot().yCm());
  return scoreMap(in);
}

}  // namespace nxtmap::mapping
