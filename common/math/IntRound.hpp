#pragma once
#include <cstdint>

#include "common/check/CodeSize.hpp"

namespace nxtmap {

// n / d to the nearest integer, ties away from zero (d > 0). C++'s / truncates towards zero, up to a whole unit
// every time: summed over many small steps (a sweep's 36 turns of 87 mrad, each scaled by the turn error) that is a
// bias. Out of line: a 64-bit division inlined at every use costs the brick's flash (CodeSize.hpp).
NXTMAP_OUT_OF_LINE constexpr int64_t divRound(int64_t n, int64_t d) {
  return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}

}  // namespace nxtmap
