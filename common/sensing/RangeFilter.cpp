#include "common/sensing/RangeFilter.hpp"

namespace nxtmap {

RangeFilter::Verdict RangeFilter::verdictOf(uint8_t raw) const {
  if (raw == 255) return Verdict::NoEcho;
  if (raw <= geometry_.minCm) return Verdict::TooNear;
  if (raw > geometry_.maxCm) return Verdict::TooFar;
  return Verdict::Accepted;
}

void RangeFilter::add(uint8_t raw) {
  if (done()) return;
  raw_[count_++] = raw;
}

bool RangeFilter::done() const {
  if (count_ >= kMaxSamples) return true;
  if (count_ < kAgree) return false;
  const Verdict first = verdictOf(raw_[0]);
  for (uint8_t i = 1; i < kAgree; ++i) {
    if (verdictOf(raw_[i]) != first) return false;
  }
  if (first != Verdict::Accepted) return true;
  int16_t lo = raw_[0], hi = raw_[0];
  for (uint8_t i = 1; i < kAgree; ++i) {
    if (raw_[i] < lo) lo = raw_[i];
    if (raw_[i] > hi) hi = raw_[i];
  }
  return hi - lo <= kToleranceCm;
}

RangeReading RangeFilter::result() const {
  RangeReading r;
  r.samples = count_;
  uint8_t accepted[kMaxSamples];
  uint8_t nAccepted = 0, nNoEcho = 0, nNear = 0, nFar = 0;
  for (uint8_t i = 0; i < count_; ++i) {
    switch (verdictOf(raw_[i])) {
      case Verdict::Accepted: accepted[nAccepted++] = raw_[i]; break;
      case Verdict::NoEcho: ++nNoEcho; break;
      case Verdict::TooNear: ++nNear; break;
      case Verdict::TooFar: ++nFar; break;
    }
  }
  // A majority of echoes inside the range wins; otherwise the most common rejection.
  if (2 * nAccepted <= count_) {
    r.status = RangeStatus::Inconsistent;
    if (2 * nNoEcho > count_) r.status = RangeStatus::NoEcho;
    if (2 * nNear > count_) r.status = RangeStatus::TooNear;
    if (2 * nFar > count_) r.status = RangeStatus::TooFar;
    if (2 * (nNoEcho + nFar) > count_ && r.status == RangeStatus::Inconsistent) {
      r.status = RangeStatus::TooFar;  // no echo and too far agree: nothing within range
    }
    return r;
  }
  // Median by insertion sort (at most 10 values), then the mean of those near it.
  for (uint8_t i = 1; i < nAccepted; ++i) {
    const uint8_t v = accepted[i];
    uint8_t j = i;
    while (j > 0 && accepted[j - 1] > v) {
      accepted[j] = accepted[j - 1];
      --j;
    }
    accepted[j] = v;
  }
  const int16_t median = accepted[nAccepted / 2];
  int16_t sum = 0;
  uint8_t n = 0;
  for (uint8_t i = 0; i < nAccepted; ++i) {
    const int16_t d = static_cast<int16_t>(accepted[i] - median);
    if (d <= kToleranceCm && d >= -kToleranceCm) {
      sum = static_cast<int16_t>(sum + accepted[i]);
      ++n;
    }
  }
  if (2 * n <= count_) {
    r.status = RangeStatus::Inconsistent;
    return r;
  }
  r.status = RangeStatus::Good;
  r.cm = static_cast<int16_t>((sum + n / 2) / n);
  return r;
}

RangeReading RangeFilter::filter(const RangeGeometry& geometry, const uint8_t* raw, uint8_t n) {
  RangeFilter f(geometry);
  for (uint8_t i = 0; i < n && !f.done(); ++i) f.add(raw[i]);
  return f.result();
}

}  // namespace nxtmap
