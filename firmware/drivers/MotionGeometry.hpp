#pragma once
#include <cstdint>

#include "common/math/IntRound.hpp"

namespace nxtmap::fw {

// The drive's dimensions, in millimetres, and the encoder resolution. Converts distances, cells and
// turns into wheel counts (degrees of wheel rotation) with integers only; pi is taken as 355/113.
struct MotionGeometry {
  int32_t wheelDiameterMm = 56;  // the NXT 56 x 26 tyre
  int32_t trackMm = 112;         // wheel centre to wheel centre
  int32_t cellMm = 200;          // one grid cell
  int32_t countsPerTurn = 360;   // half-decoded encoder, 1 count = 1 degree

  // Counts for a straight drive of `mm` (negative = backwards): mm / (pi * d) * countsPerTurn.
  constexpr int32_t countsForMm(int32_t mm) const {
    return roundDiv(static_cast<int64_t>(mm) * countsPerTurn * 113, static_cast<int64_t>(wheelDiameterMm) * 355);
  }
  constexpr int32_t countsForCells(int32_t cells) const { return countsForMm(cells * cellMm); }
  // Counts each wheel turns (one forward, one back) to spin the robot on the spot by `mrad`
  // milliradians: arc = mrad / 1000 * track / 2, counts = arc / (pi * d) * countsPerTurn.
  constexpr int32_t countsForMrad(int32_t mrad) const {
    return roundDiv(static_cast<int64_t>(mrad) * trackMm * countsPerTurn * 113,
                    static_cast<int64_t>(2000) * wheelDiameterMm * 355);
  }
  // The inverses, for what the encoders measured: mm driven, and mrad spun for `counts` of each
  // wheel in opposite directions.
  constexpr int32_t mmForCounts(int32_t counts) const {
    return roundDiv(static_cast<int64_t>(counts) * wheelDiameterMm * 355, static_cast<int64_t>(countsPerTurn) * 113);
  }
  constexpr int32_t mradForCounts(int32_t counts) const {
    return roundDiv(static_cast<int64_t>(counts) * 2000 * wheelDiameterMm * 355,
                    static_cast<int64_t>(trackMm) * countsPerTurn * 113);
  }
  // Spin by `eighths` of a full turn: pi cancels, counts = track * eighths * countsPerTurn / (8 * d).
  constexpr int32_t countsForTurn(int32_t eighths) const {
    return static_cast<int32_t>(
        roundDiv(static_cast<int64_t>(trackMm) * eighths * countsPerTurn, static_cast<int64_t>(8) * wheelDiameterMm));
  }

 private:
  static constexpr int32_t roundDiv(int64_t num, int64_t den) { return static_cast<int32_t>(divRound(num, den)); }
};

}  // namespace nxtmap::fw
