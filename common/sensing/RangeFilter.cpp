#include "common/sensing/RangeFilter.hpp"

namespace nxtmap {

RangeFilter::Verdict RangeFilter::verdictOf(uint8_t raw) const {
  if (raw == 255) return Verdict::NoEcho;
  const int16_t cm = geometry_.trueCm(raw);  // the limits are true distances
  if (cm <= geometry_.minCm) return Verdict::TooNear;
  if (cm > geometry_.maxCm) return Verdict::TooFar;
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

namespace {
// The sum of the values within kToleranceCm of their median (sorts `v` in place); n > 0.
// `near` is how many values went into it.
int16_t sumNearMedian(uint8_t* v, uint8_t n, int16_t tolerance, uint8_t& near) {
  for (uint8_t i = 1; i < n; ++i) {  // insertion sort: at most 10 values
    const uint8_t x = v[i];
    uint8_t j = i;
    while (j > 0 && v[j - 1] > x) {
      v[j] = v[j - 1];
      --j;
    }
    v[j] = x;
  }
  const int16_t median = v[n / 2];
  int16_t sum = 0;
  near = 0;
  for (uint8_t i = 0; i < n; ++i) {
    const int16_t d = static_cast<int16_t>(v[i] - median);
    if (d <= tolerance && d >= -tolerance) {
      sum = static_cast<int16_t>(sum + v[i]);
      ++near;
    }
  }
  return sum;
}
}  // namespace

RangeReading RangeFilter::result() const {
  RangeReading r;
  r.samples = count_;
  uint8_t accepted[kMaxSamples], far[kMaxSamples];
  uint8_t nAccepted = 0, nNoEcho = 0, nNear = 0, nFar = 0;
  for (uint8_t i = 0; i < count_; ++i) {
    switch (verdictOf(raw_[i])) {
      case Verdict::Accepted: accepted[nAccepted++] = raw_[i]; break;
      case Verdict::NoEcho: ++nNoEcho; break;
      case Verdict::TooNear: ++nNear; break;
      case Verdict::TooFar: far[nFar++] = raw_[i]; break;
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
    // Beyond the range: the echo's distance too when a majority of the samples agree on it.
    uint8_t n = 0;
    if (r.status == RangeStatus::TooFar && nFar > 0) {
      const int16_t sum = sumNearMedian(far, nFar, kToleranceCm, n);
      if (2 * n > count_) r.cm = geometry_.trueCm(sum, n);
    }
    return r;
  }
  uint8_t n = 0;
  const int16_t sum = sumNearMedian(accepted, nAccepted, kToleranceCm, n);
  if (2 * n <= count_) {
    r.status = RangeStatus::Inconsistent;
    return r;
  }
  r.status = RangeStatus::Good;
  r.cm = geometry_.trueCm(sum, n);
  return r;
}

RangeReading RangeFilter::filter(const RangeGeometry& geometry, const uint8_t* raw, uint8_t n) {
  RangeFilter f(geometry);
  for (uint8_t i = 0; i < n && !f.done(); ++i) f.add(raw[i]);
  return f.result();
}

}  // namespace nxtmap
