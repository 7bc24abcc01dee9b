// MapAlignment: the rigid move of a finished map (rotation about the start point, then a shift) that best
// agrees with the scene, so a map that is right but laid down a few degrees off is told apart from a
// wrong one. Agreement: the map's occupied cells hold an obstacle and its free cells hold none, by the
// safe rule (sim::rasterizeScene).
// Search: a coarse-to-fine grid over rotation and shift scored against a precomputed field (per plane
// point cellCm / 8 apart, how near an obstacle is), then the best few candidates scored exactly and
// improved a step at a time by the exact count (ties: the smaller move; the unmoved map competes too).
#pragma once
#include <vector>

#include "common/grid/CellState.hpp"
#include "host/sim/GridFrame.hpp"
#include "host/sim/Scene.hpp"

namespace nxtmap::mapping {

// One cell a map holds as known, in the robot's grid (the truth raster's col/row; may lie outside it).
struct KnownCell {
  int col = 0, row = 0;
  CellState state = CellState::Free;
};

struct AlignmentSearch {
  double maxRotationDeg = 15.0;  // rotations -max..+max about the start point
  double rotationStepDeg = 0.5;  // finest rotation step
  double maxShiftCells = 1.0;    // shifts -max..+max along each grid axis, cells
  double shiftStepCells = 0.25;  // finest shift step, cells
  int exactCandidates = 12;      // best approximate candidates scored exactly
};

struct Alignment {
  double rotationDeg = 0.0;               // + clockwise, about the start cell's centre
  double shiftCol = 0.0, shiftRow = 0.0;  // cells along the original grid's col and row axes
  sim::GridFrame frame;                   // the moved grid: map cell (c, r) lies at frame.toPlane(c, r)
  int agreeing = 0;                       // known cells that agree with the truth on `frame`
};

// The grid `frame` turned by rotationDeg about the centre of (startCol, startRow), then shifted.
sim::GridFrame movedFrame(const sim::GridFrame& frame, int startCol, int startRow, double rotationDeg, double shiftCol,
                          double shiftRow);

// Known cells that agree with the scene rasterised on `frame` (cells 0..width-1 x 0..height-1; outside them
// the truth is blocked).
int agreeingCells(const sim::Scene& scene, const sim::GridFrame& frame, int width, int height,
                  const std::vector<KnownCell>& known);

// The best alignment of `known` (cells of `frame`, truth raster width x height) to the scene.
Alignment alignMap(const sim::Scene& scene, const sim::GridFrame& frame, int startCol, int startRow, int width,
                   int height, const std::vector<KnownCell>& known, const AlignmentSearch& search = {});

}  // namespace nxtmap::mapping
