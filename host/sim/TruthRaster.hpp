// TruthRaster: the truth a mapping run is scored against, drawn on the robot's grid (GridFrame) by the
// SAFE rule: a cell is blocked if any part of an obstacle lies in its open interior, i.e. a ring side or a
// wall passes through the interior, a disc overlaps it, or the interior lies in solid space (even-odd rule
// over the rings, the plane outside every ring solid). A segment lying exactly on a cell's border blocks
// neither neighbour, so a raster world traced into rings at its own resolution and frame comes back cell
// for cell.
#pragma once

#include "host/sim/GridFrame.hpp"
#include "host/sim/Scene.hpp"
#include "host/sim/World.hpp"

#include <string>

namespace nxtmap::sim {

// Cells 0..width-1 x 0..height-1 of `frame` (width, height >= 1); the World's resolution is frame.cellCm.
World rasterizeScene(const Scene& scene, const GridFrame& frame, int width, int height, const std::string& name);

// A grid laid over a whole scene for a robot starting at a plane point.
struct Placement {
  GridFrame frame;                 // cell (0, 0) at frame.originCm
  int startCol = 0, startRow = 0;  // the cell whose centre is the start point
  int width = 0, height = 0;       // cells covering the scene's bounds (and the start) plus one cell margin
};

// The grid of cellCm cells turned to compass frameHeadingDeg with a cell centred on startCm. For a raster
// world traced at the robot's own resolution, a start at a cell centre and heading 0 this is the raster's
// own grid (when the trace's bounds lie one cell inside the raster, as a blocked border gives).
Placement placeOnGrid(const Scene& scene, const Vec2& startCm, double frameHeadingDeg, double cellCm);

}  // namespace nxtmap::sim
