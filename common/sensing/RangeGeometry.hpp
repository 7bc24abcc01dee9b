#pragma once
#include <cstdint>

namespace nxtmap {

// How a range in centimetres relates to cells. All distances in whole centimetres.
// The sensor sits `mountCm` ahead of the robot's cell centre; readings are measured from it.
struct RangeGeometry {
  int16_t cellCm = 10;  // cell edge: 10 cm in the published experiments, 20 cm on the NXT; >= 1 (a divisor)
  int16_t minCm = 5;    // readings at or below are "too near" (published: 5 cm)
  int16_t maxCm = 100;  // readings above are "too far" (published: 1 m)
  int16_t mountCm = 0;  // sensor face ahead of the cell centre
  // Farthest echo that is placed in the cell on the sensor's axis. A beam of half-angle a reaches
  // into the neighbouring cells beyond (cellCm / 2) / tan(a) - mountCm, so a farther echo may come
  // from beside the axis: it only proves the cells before it free. 0 = up to maxCm (the published rule).
  int16_t sureCm = 0;
  // The sensor's blind zone: an obstacle nearer than this to the sensor returns no echo at all (the NXT
  // sensor: about 7 cm), so "no echo" cannot vouch for a cell reaching into it. 0: a near obstacle
  // reads too near (the published model).
  int16_t blindCm = 0;

  // Cells a "nothing within range" reading proves free: those wholly inside the range.
  constexpr int16_t freeCells() const { return static_cast<int16_t>((2 * (maxCm + mountCm) - cellCm) / (2 * cellCm)); }
  // Farthest cell whose near face lies inside the range, so a hit there is seen.
  constexpr int16_t hitCells() const { return static_cast<int16_t>((2 * (maxCm + mountCm) + cellCm) / (2 * cellCm)); }
  // Cells (1 = adjacent) whose near face lies inside the blind zone.
  constexpr int16_t blindCells() const {
    return blindCm <= 0 ? 0 : static_cast<int16_t>((2 * (blindCm + mountCm) + cellCm - 1) / (2 * cellCm));
  }
  // Whether an echo at `cm` may be placed on the axis (see sureCm).
  constexpr bool sureHit(int16_t cm) const { return sureCm == 0 || cm <= sureCm; }
  // The cell (1 = adjacent) holding the obstacle whose near face is `cm` from the sensor.
  // Robust to errors under half a cell: the near face of cell k is (k - 1/2) cells from the centre.
  constexpr int16_t hitCell(int16_t cm) const { return static_cast<int16_t>((cm + mountCm + cellCm) / cellCm); }
};

}  // namespace nxtmap
