// WorldTruth: the ground-truth oracle that scores mapping runs — which cells a robot could reach and see.
#pragma once

#include "host/sim/World.hpp"

#include <cstdint>
#include <vector>

namespace nxtmap::sim {

struct Observability {
  std::vector<uint8_t> reachable;   // per cell, row-major width*height: 1 = the start, or free and 4-connected to it
  std::vector<uint8_t> observable;  // per cell, row-major width*height: 1 = seen along an axis from a reachable cell
  int reachableCount = 0;           // cells with reachable = 1
  int observableFree = 0;           // observable free cells
  int observableOccupied = 0;       // observable blocked cells
};

// Cell X is observable iff, for some reachable cell R and one of the 4 axis directions, X lies k cells from R
// along it, every cell strictly between is free, and (X free and 1 <= k <= freeCells) or
// (X blocked and 1 <= k <= hitCells). Reachable cells are not observable by themselves; cells outside the map
// never are. The start cell is reachable even when blocked (a wall reaching a sliver into the cell the robot
// stands in): what is 4-connected to it is reached from it; a start outside the map reaches nothing.
Observability computeObservability(const World& world, int startCol, int startRow, int freeCells, int hitCells);

}  // namespace nxtmap::sim
