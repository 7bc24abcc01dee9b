#pragma once
#include <cstdint>

namespace nxtmap {

// The integer square root of v: the largest r with r * r <= v (bit by bit, no division, no floating point; the
// brick has neither hardware). For variances (mm^2, mrad^2) and lengths from squared components.
constexpr uint64_t isqrt(uint64_t v) {
  uint64_t r = 0, bit = uint64_t{1} << 62;
  while (bit > v) bit >>= 2;
  while (bit != 0) {
    if (v >= r + bit) {
      v -= r + bit;
      r = (r >> 1) + bit;
    } else {
      r >>= 1;
    }
    bit >>= 2;
  }
  return r;
}
static_assert(isqrt(0) == 0 && isqrt(15) == 3 && isqrt(16) == 4 && isqrt(uint64_t{1} << 62) == uint64_t{1} << 31,
              "isqrt: the largest r with r * r <= v");

}  // namespace nxtmap
