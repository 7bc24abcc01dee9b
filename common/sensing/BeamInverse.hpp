#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/sensing/RangeGeometry.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap {

// One cell's share of a reading's evidence, relative to the sensor's cell and axis.
struct ConeMark {
  int8_t along = 0;   // cells out along the sensor's axis, 1 = adjacent
  int8_t side = 0;    // -1: the cell left of the axis, 0: on it, +1: right of it (clockwise, rotate(d, 1))
  int8_t weight = 0;  // observations for MapLayers: < 0 free (observeFree |weight| times), > 0 occupied
};

// The cell a mark names, for a reading taken from `from` looking along `d`.
constexpr Cell coneCell(Cell from, Dir d, const ConeMark& m) {
  return advance(advance(from, d, m.along), rotate(d, 1), m.side);
}

// At most this many marks per reading: 3 cells across for 16 cells out (RangeGeometry::hitCells()).
constexpr int kMaxConeMarks = 48;

// The inverse beam model for mapping (the cells a reading says something about), a pure function of the reading,
// the geometry and the cone's half-angle (coneHalfMrad, 0..600 mrad: the beam's width at the ranges read).
// Ranges are whole cm from the sensor's face; the near face of cell k (1 = adjacent) is (k - 1/2) cells - mountCm
// away, its far face (k + 1/2) cells - mountCm. The first echo is the nearest thing in the cone, so:
//  - an echo at r: the axis cells before the echo's cell (RangeGeometry::hitCell) are free, weight 2; a cell beside
//    the axis is free, weight 1, where the cone covers a quarter of its width from its near face on (half-width
//    r tan a >= 3/4 cell there) and all of it lies nearer than r (its far face / cos a < r). The echo's cell is
//    occupied, weight 2, while the arc at r (half-width r tan a) is narrower than a cell; wider, the evidence is
//    shared: weight 1 on the axis cell and on the cells either side (small angles: they are taken at the same
//    distance along). This replaces RangeGeometry::sureCm's "far echoes mark nothing".
//  - too far (an echo beyond maxCm): as an echo at maxCm without the hit; the axis up to freeCells().
//  - no echo: the axis cells up to freeCells(), weight 1 only (specular and soft losses answer nothing too).
//  - too near: the adjacent cell occupied, weight 2; inconsistent: nothing.
// What needs the map stays with the caller: a ray stops at a cell already known occupied (RayMarker), and a
// "no echo" vouches for nothing while the blind zone is unknown (RangeGeometry::blindCm).
// Fills `out` (caller-owned, `capacity` marks), nearest cells first, axis before its sides; returns how many it
// wrote (fewer than the reading implies only when the capacity is short).
int inverseBeam(const RangeGeometry& geometry, int32_t coneHalfMrad, const RangeReading& reading, ConeMark* out,
                int capacity);

}  // namespace nxtmap
