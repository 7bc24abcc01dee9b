#pragma once
#include <cstdint>

namespace nxtmap {

// The figures the method reports (section 5.2), counted by the explorer as events arrive.
struct Counters {
  uint32_t sensorRequests = 0;  // filtered readings asked for ("sensor count")
  uint32_t rawSamples = 0;      // raw pings behind them
  uint32_t cellsMoved = 0;      // one per cell travelled
  uint32_t turnEighths = 0;     // 2 per 90 deg turn, 1 per 45 deg
  uint32_t blockedMoves = 0;    // moves the wheels could not complete
  uint32_t correctionMrad = 0;  // small steering rotations that keep the robot on the grid, mrad

  // Time in half cell units: one unit per cell moved and per 90 deg turn (half for 45 deg);
  // steering corrections count by their angle (785 mrad = 45 deg = one half unit).
  constexpr uint32_t timeHalfUnits() const { return 2 * cellsMoved + turnEighths + correctionMrad / 785; }

  // Sums another run's figures into these.
  constexpr Counters& operator+=(const Counters& o) {
    sensorRequests += o.sensorRequests;
    rawSamples += o.rawSamples;
    cellsMoved += o.cellsMoved;
    turnEighths += o.turnEighths;
    blockedMoves += o.blockedMoves;
    correctionMrad += o.correctionMrad;
    return *this;
  }
};

}  // namespace nxtmap
