#pragma once
#include <cstdint>

#include "common/sensing/RangeGeometry.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap {

// Turns raw ultrasonic samples (0..255 cm, 255 = no echo) into one trusted reading.
// Samples at/below minCm or above maxCm are rejected; up to kMaxSamples are taken and the
// accepted ones averaged after dropping those far from their median. Sampling stops early once
// the first kAgree samples all give the same verdict. Feed with add() until done().
class RangeFilter {
 public:
  static constexpr uint8_t kMaxSamples = 10;
  static constexpr uint8_t kAgree = 3;
  static constexpr int16_t kToleranceCm = 4;  // spread accepted around the median

  explicit RangeFilter(const RangeGeometry& geometry) : geometry_(geometry) {}

  void reset() { count_ = 0; }
  // Adds one raw sample (ignored once done()).
  void add(uint8_t raw);
  bool done() const;
  uint8_t samples() const { return count_; }
  // The reading from the samples so far (call when done()).
  RangeReading result() const;

  // One-shot helper for tables and tests: filters a whole sequence, consuming what it needs.
  static RangeReading filter(const RangeGeometry& geometry, const uint8_t* raw, uint8_t n);

 private:
  enum class Verdict : uint8_t { Accepted, NoEcho, TooNear, TooFar };
  Verdict verdictOf(uint8_t raw) const;

  RangeGeometry geometry_;
  uint8_t raw_[kMaxSamples] = {};
  uint8_t count_ = 0;
};

}  // namespace nxtmap
