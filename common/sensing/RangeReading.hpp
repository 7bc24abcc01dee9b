#pragma once
#include <cstdint>

namespace nxtmap {

// Status of one filtered reading of one sensor.
enum class RangeStatus : uint8_t {
  Good = 0,          // an echo inside (minCm, maxCm]: an obstacle at `cm`
  NoEcho = 1,        // the sensor answered 255: nothing within its reach
  TooNear = 2,       // at or below minCm: an obstacle closer than the trusted minimum
  TooFar = 3,        // above maxCm: nothing within the trusted range
  Inconsistent = 4,  // the samples disagree: nothing can be concluded
};

// One filtered reading: the explorer's unit of sensing ("one sensor request").
struct RangeReading {
  RangeStatus status = RangeStatus::NoEcho;
  // Good: averaged distance of the accepted samples. TooFar: the echo beyond the trusted range
  // when a majority of the samples agree on it (0 when they do not): never mapped, only matched
  // against walls already known (pose readings). 0 otherwise.
  int16_t cm = 0;
  uint8_t samples = 0;  // raw samples the filter consumed, 1..RangeFilter::kMaxSamples
};

}  // namespace nxtmap
