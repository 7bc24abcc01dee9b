#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// The method's four diagonal propagations (section 3.5.2), in the explorer's frame:
// forward = +y (the robot's initial heading), right = +x.
enum class Propagation : uint8_t { ForwardRight = 0, ForwardLeft = 1, BackwardRight = 2, BackwardLeft = 3 };

// How a propagation ended: a wall ahead vertically (the thesis's hitup/hitdown), a wall
// sideways (hitright/hitleft), a corner (success, "done"), or the stop heuristic (the next
// diagonal move was already travelled).
enum class PropagationOutcome : uint8_t { HitVertical = 0, HitHorizontal = 1, Corner = 2, Reused = 3 };

constexpr int propagationDx(Propagation p) {
  return (p == Propagation::ForwardRight || p == Propagation::BackwardRight) ? 1 : -1;
}
constexpr int propagationDy(Propagation p) {
  return (p == Propagation::ForwardRight || p == Propagation::ForwardLeft) ? 1 : -1;
}
constexpr Dir verticalDir(Propagation p) { return propagationDy(p) > 0 ? Dir::North : Dir::South; }
constexpr Dir horizontalDir(Propagation p) { return propagationDx(p) > 0 ? Dir::East : Dir::West; }
constexpr Propagation propagationOf(int sx, int sy) {
  return sy > 0 ? (sx > 0 ? Propagation::ForwardRight : Propagation::ForwardLeft)
                : (sx > 0 ? Propagation::BackwardRight : Propagation::BackwardLeft);
}

// The transitions between propagations, as the thesis lists them per propagation.
// Rows: the propagation that ended; columns: HitVertical, HitHorizontal, Corner.
// (reading) For forward-left the thesis prints "wall in front -> backward-right" and
// "corner -> backward-left", copied from forward-right; the other three propagations all turn
// back only along the blocked axis on a wall and reverse both on a corner, so forward-left
// follows them: wall in front -> backward-left, corner -> backward-right.
constexpr Propagation kPropagationTable[4][3] = {
    /* ForwardRight  */ {Propagation::BackwardRight, Propagation::ForwardLeft, Propagation::BackwardLeft},
    /* ForwardLeft   */ {Propagation::BackwardLeft, Propagation::ForwardRight, Propagation::BackwardRight},
    /* BackwardRight */ {Propagation::ForwardRight, Propagation::BackwardLeft, Propagation::ForwardLeft},
    /* BackwardLeft  */ {Propagation::ForwardLeft, Propagation::BackwardRight, Propagation::ForwardRight},
};

constexpr Propagation nextPropagation(Propagation p, PropagationOutcome o) {
  return kPropagationTable[static_cast<int>(p)][static_cast<int>(o) < 3 ? static_cast<int>(o) : 2];
}

constexpr const char* propagationName(Propagation p) {
  return p == Propagation::ForwardRight    ? "forward-right"
         : p == Propagation::ForwardLeft   ? "forward-left"
         : p == Propagation::BackwardRight ? "backward-right"
                                           : "backward-left";
}
constexpr const char* outcomeName(PropagationOutcome o) {
  return o == PropagationOutcome::HitVertical     ? "wall ahead"
         : o == PropagationOutcome::HitHorizontal ? "wall aside"
         : o == PropagationOutcome::Corner        ? "corner"
                                                  : "path reused";
}

}  // namespace nxtmap
