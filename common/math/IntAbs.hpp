#pragma once
#include <cstdint>

namespace nxtmap {

// Magnitudes of signed integers (never of the type's minimum: ranges, offsets and angles stay far from it).
constexpr int32_t abs32(int32_t v) { return v < 0 ? -v : v; }
constexpr int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

}  // namespace nxtmap
