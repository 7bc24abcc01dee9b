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
  // Where walls' faces may lie. 0: on cell edges (the published raster worlds): an echo is rounded to the
  // nearest edge, robust to any error under half a cell. m > 0: anywhere (a real room): an echo marks the cell
  // holding its face (brought echoMarginCm nearer), the pilot learns where each wall's face lies in its cell
  // (FaceLines), and the start's snap lays the nearest faces 2m past a cell edge, a face not yet learnt taken
  // to lie there too. 0..cellCm / 4. (The RAM-run firmware image has no room for it, nor for FaceLines: it keeps
  // faces on edges.)
  int8_t faceMarginCm = 0;
  // With faces anywhere: an echo marks the cell holding the face brought this many cm nearer (the reading's
  // error), so a wall reaching a sliver into a cell still marks that cell occupied; a face less than this past
  // an edge marks the cell before it, a wall on open floor. 0..faceMarginCm.
  int8_t echoMarginCm = 0;
  // The sensor's linear error, as measured for its kind: raw = true * scalePer10k / 10000 + biasMm (the LEGO
  // 9846 sensor: 0.9757 x + 1.88 cm, docs/nxt-sonar-and-odometry.md). RangeFilter takes it off every echo it
  // reports, so a reading is the true distance; 10000 and 0 (the default): none. scalePer10k 5000..20000,
  // |biasMm| <= 100.
  int16_t scalePer10k = 10000;
  int16_t biasMm = 0;
#ifndef NXTMAP_NO_START_SQUARING
  constexpr bool facesAnywhere() const { return faceMarginCm > 0; }
#else
  constexpr bool facesAnywhere() const { return false; }
#endif

  // The true distance (whole cm, rounded, 0..254) of an echo the sensor read as the mean of `n` (1..10) whole-cm
  // samples summing to `sumCm` (each 0..254); with no linear error, the samples' mean rounded half up.
  constexpr int16_t trueCm(int32_t sumCm, int32_t n = 1) const {
    const int32_t mmTimesN = (sumCm * 10 - biasMm * n) * 10000 / scalePer10k;  // n times the true mm
    const int32_t cm = (mmTimesN + 5 * n) / (10 * n);
    return static_cast<int16_t>(cm < 0 ? 0 : (cm > 254 ? 254 : cm));
  }

  // Cells a "nothing within range" reading proves free: those wholly inside the range.
  constexpr int16_t freeCells() const { return static_cast<int16_t>((2 * (maxCm + mountCm) - cellCm) / (2 * cellCm)); }
  // Farthest cell whose near face lies inside the range, so a hit there is seen.
  constexpr int16_t hitCells() const {
    return facesAnywhere() ? hitCell(maxCm) : static_cast<int16_t>((2 * (maxCm + mountCm) + cellCm) / (2 * cellCm));
  }
  // Cells (1 = adjacent) whose near face lies inside the blind zone.
  constexpr int16_t blindCells() const {
    return blindCm <= 0 ? 0 : static_cast<int16_t>((2 * (blindCm + mountCm) + cellCm - 1) / (2 * cellCm));
  }
  // Whether an echo at `cm` may be placed on the axis (see sureCm).
  constexpr bool sureHit(int16_t cm) const { return sureCm == 0 || cm <= sureCm; }
  // The cell (1 = adjacent) holding the obstacle whose near face is `cm` from the sensor (see faceMarginCm):
  // published, the near face of cell k is (k - 1/2) cells from the centre.
  constexpr int16_t hitCell(int16_t cm) const {
    if (!facesAnywhere()) return static_cast<int16_t>((cm + mountCm + cellCm) / cellCm);
    const int32_t k = (2 * (cm + mountCm - echoMarginCm) + cellCm) / (2 * cellCm);
    return static_cast<int16_t>(k < 1 ? 1 : k);
  }
  // Where a wall cell k cells out is taken to have its face, mm from the cell centre, until learnt otherwise:
  // (k - 1/2) cells, plus 2 * faceMarginCm past the edge when faces lie anywhere (where the snap lays them).
  constexpr int32_t faceMm(int32_t k) const {
    return (2 * k - 1) * cellCm * 5 + (facesAnywhere() ? 20 * faceMarginCm : 0);
  }
};

}  // namespace nxtmap
