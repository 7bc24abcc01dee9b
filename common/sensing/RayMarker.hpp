#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/MapLayers.hpp"
#include "common/sensing/RangeGeometry.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap {

// The method's marking rules for one filtered reading taken from `from` looking along `d`:
//  - an echo: the cells before the obstacle become free, the obstacle's cell occupied;
//  - nothing within range (no echo, too far): every cell wholly inside the range becomes free; but a
//    "no echo" says nothing while a cell reaching into the sensor's blind zone (RangeGeometry::blindCm)
//    is not already known free: an obstacle there would have answered nothing too (unless trustBlind);
//  - too near: the adjacent cell is occupied (an obstacle closer than the trusted minimum);
//  - inconsistent: nothing is marked.
// A ray never passes a cell the map already holds as occupied (the robot cannot read through
// a wall): that cell gets one observation as free and marking stops there. Nor does it pass the
// edge of the grid's capacity: a room larger than the grid is mapped up to that edge.
struct RayMarkResult {
  int16_t cellsMarked = 0;  // observations written
  bool clipped = false;     // a cell did not fit in the grid's capacity: marking stopped before it
  bool conclusive = false;  // the reading said something (not Inconsistent)
};

// trustBlind: the blind zone is taken as clear (where the robot was set down: see Explorer).
RayMarkResult markRay(MapLayers& map, const RangeGeometry& geometry, Cell from, Dir d, const RangeReading& reading,
                      bool trustBlind = false);

}  // namespace nxtmap
