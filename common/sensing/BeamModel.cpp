#include "common/sensing/BeamModel.hpp"

#include "common/check/Check.hpp"

namespace nxtmap {
namespace {

// e^-k in Q24, k = 0..16, and e^(-j/8) in Q16, j = 0..7: e^(-n/8) = kWhole[n / 8] * kEighth[n % 8] / 2^16.
constexpr uint32_t kWhole[17] = {16777216, 6171993, 2270549, 835288, 307285, 113044, 41587, 15299, 5628,
                                 2070,     762,     280,     103,    38,     14,     5,     2};
constexpr uint32_t kEighth[8] = {65536, 57835, 51039, 45042, 39750, 35079, 30957, 27319};

// e^(-n/8) in Q24 for n = 0..kMaxExpCost + 1 (the last 0), built at compile time.
struct ExpTable {
  uint32_t q24[BeamModel::kMaxExpCost + 2] = {};
  constexpr ExpTable() {
    for (int n = 0; n <= BeamModel::kMaxExpCost; ++n) {
      q24[n] = static_cast<uint32_t>((static_cast<uint64_t>(kWhole[n / 8]) * kEighth[n % 8] + (1u << 15)) >> 16);
    }
  }
};
constexpr ExpTable kExp;

// e^(-x/8) in Q24 for x = num / den eighth-nats (num >= 0, 0 < den < 2^23), linear between whole eighth-nats
// (within 0.2 %).
uint32_t expBetween(uint32_t num, uint32_t den) {
  const uint32_t n = num / den;
  if (n > BeamModel::kMaxExpCost) return 0;
  const uint32_t a = kExp.q24[n], b = kExp.q24[n + 1];
  const uint32_t f = ((num - n * den) << 8) / den;  // the fraction between n and n + 1, 1/256
  return a - static_cast<uint32_t>((static_cast<uint64_t>(a - b) * f) >> 8);
}

constexpr uint32_t q16(int32_t perMille) { return static_cast<uint32_t>(perMille * 65536 / 1000); }

}  // namespace

BeamModel::BeamModel(const BeamParams& params) : params_(params) {
  NXTMAP_CHECK(params.valid());
  hitW_ = q16(params.hitPerMille);
  shortW_ = q16(params.shortPerMille);
  maxW_ = q16(params.maxPerMille);
  // The gaussian's mass per cm at its peak: 10 mm / (sigma_mm sqrt(2 pi)), sqrt(2 pi) = 2.50663.
  hitPeakQ24_ = static_cast<uint32_t>(uint64_t{kOne} * 1000000 / (static_cast<uint64_t>(params.hitSigmaMm) * 250663));
  randQ24_ = static_cast<uint32_t>(uint64_t{kOne} * params.randPerMille / 1000 / (params.randomMaxCm + 1));
}

uint32_t BeamModel::expQ24(int32_t n) {
  if (n <= 0) return kOne;
  return n > kMaxExpCost ? 0 : kExp.q24[n];
}

uint8_t BeamModel::costOf(uint32_t pQ24) {
  if (pQ24 == 0) return kMaxCost;
  if (pQ24 >= kOne) return 0;
  // The largest n with e^(-n/8) >= p (the table falls with n), then rounded to the nearer of n, n + 1.
  int32_t lo = 0, hi = kMaxExpCost;
  while (lo < hi) {
    const int32_t mid = (lo + hi + 1) / 2;
    if (kExp.q24[mid] >= pQ24) {
      lo = mid;
    } else {
      hi = mid - 1;
    }
  }
  if (lo < kMaxExpCost && (kExp.q24[lo] + kExp.q24[lo + 1]) / 2 > pQ24) ++lo;
  return static_cast<uint8_t>(lo);
}

int32_t BeamModel::expectedReadingMm(int16_t trueCm) const {
  return (static_cast<int32_t>(trueCm) * 10 * params_.scalePer10k + 5000) / 10000 + params_.biasMm;
}

int32_t BeamModel::echoPerMille(int16_t trueCm) const {
  if (trueCm < 0 || trueCm >= params_.limitCm) return 0;
  if (trueCm <= params_.reliableCm) return 1000;
  return 1000 * (params_.limitCm - trueCm) / (params_.limitCm - params_.reliableCm);
}

uint32_t BeamModel::hitQ24(int16_t zCm, int32_t expectedMm) const {
  const int32_t d = static_cast<int32_t>(zCm) * 10 - expectedMm;  // mm, |d| < 2^13
  const uint32_t var = static_cast<uint32_t>(params_.hitSigmaMm) * static_cast<uint32_t>(params_.hitSigmaMm);
  // d^2 / (2 sigma^2) nats = 4 d^2 / sigma^2 eighth-nats
  return static_cast<uint32_t>(
      (static_cast<uint64_t>(expBetween(static_cast<uint32_t>(4 * d * d), var)) * hitPeakQ24_) >> 24);
}

uint32_t BeamModel::shortQ24(int16_t zCm, int32_t expectedMm) const {
  const uint32_t mean = static_cast<uint32_t>(params_.shortMeanCm);
  if (expectedMm >= 0 && static_cast<int32_t>(zCm) * 10 >= expectedMm) return 0;
  const uint32_t density = expBetween(8u * static_cast<uint32_t>(zCm), mean) / mean;
  if (expectedMm < 0) return density;  // normalised over every reading
  // Times 1 / (1 - e^(-reading / mean)), the exponential cut at the expected reading, as 2^32 / within in Q8.
  const uint32_t within = kOne - expBetween(8u * static_cast<uint32_t>(expectedMm), 10 * mean);
  if (within == 0) return 0;
  return static_cast<uint32_t>((static_cast<uint64_t>(density) * (0xFFFFFFFFu / within)) >> 8);
}

uint32_t BeamModel::probability(int16_t zCm, int16_t trueCm) const {
  const uint32_t echo = q16(echoPerMille(trueCm));
  if (zCm == kNoEcho) return (maxW_ << 8) + static_cast<uint32_t>((static_cast<uint64_t>(hitW_) * (65536 - echo)) >> 8);
  if (zCm < 0 || zCm > kNoEcho) return 0;
  const int32_t expectedMm = trueCm < 0 ? -1 : expectedReadingMm(trueCm);
  uint64_t sum = zCm <= params_.randomMaxCm ? randQ24_ : 0;
  if (echo > 0) sum += (((static_cast<uint64_t>(hitW_) * echo) >> 16) * hitQ24(zCm, expectedMm)) >> 16;
  sum += (static_cast<uint64_t>(shortW_) * shortQ24(zCm, expectedMm)) >> 16;
  return static_cast<uint32_t>(sum);
}

uint8_t BeamModel::bestCost(int16_t zCm) const {
  if (zCm == kNoEcho) return cost(zCm, kNothing);
  // The true range whose expected reading is z, and its neighbours (the linear error rounds).
  const int32_t trueMm = (static_cast<int32_t>(zCm) * 10 - params_.biasMm) * 10000 / params_.scalePer10k;
  const int32_t trueCm = (trueMm + 5) / 10;
  uint8_t best = kMaxCost;
  for (int32_t t = trueCm - 1; t <= trueCm + 1; ++t) {
    if (t < 0) continue;
    const uint8_t c = cost(zCm, static_cast<int16_t>(t));
    if (c < best) best = c;
  }
  return best;
}

}  // namespace nxtmap
