#include "common/motion/WheelRecord.hpp"

namespace nxtmap {
namespace {

constexpr int32_t kMaxDriftUradPerM = 200000;  // WheelCalibration's ranges (PoseTracker holds within them)
constexpr int32_t kMaxTurnPpm = 100000;

bool within(int32_t v, int32_t limit) { return v > -limit && v < limit; }
uint32_t low(int64_t v) { return static_cast<uint32_t>(static_cast<uint64_t>(v)); }
uint32_t high(int64_t v) { return static_cast<uint32_t>(static_cast<uint64_t>(v) >> 32); }
int64_t joined(uint32_t lowWord, uint32_t highWord) {
  return static_cast<int64_t>((static_cast<uint64_t>(highWord) << 32) | lowWord);
}

}  // namespace

uint32_t WheelRecord::checkOf(const uint32_t (&words)[kWords]) {
  uint32_t c = kMagic;
  for (int i = 0; i < kWords - 1; ++i) c = ((c << 5) | (c >> 27)) ^ words[i];
  return ~c;
}

void WheelRecord::encode(const WheelCalibration& w, uint32_t (&words)[kWords]) {
  words[0] = kMagic;
  words[1] = static_cast<uint32_t>(w.driftUradPerM);
  words[2] = static_cast<uint32_t>(w.turnPpm);
  words[3] = kVersion;
  words[4] = low(w.driftVariance);
  words[5] = high(w.driftVariance);
  words[6] = low(w.turnVariance);
  words[7] = high(w.turnVariance);
  words[8] = checkOf(words);
}

bool WheelRecord::decode(const uint32_t (&words)[kWords], WheelCalibration& w) {
  if (words[0] != kMagic || words[3] != kVersion || words[kWords - 1] != checkOf(words)) return false;
  WheelCalibration r;
  r.driftUradPerM = static_cast<int32_t>(words[1]);
  r.turnPpm = static_cast<int32_t>(words[2]);
  r.driftVariance = joined(words[4], words[5]);
  r.turnVariance = joined(words[6], words[7]);
  if (!within(r.driftUradPerM, kMaxDriftUradPerM) || !within(r.turnPpm, kMaxTurnPpm)) return false;
  if (r.driftVariance <= 0 || r.turnVariance <= 0) return false;
  w = r;
  return true;
}

bool WheelRecord::same(const WheelCalibration& a, const WheelCalibration& b) {
  return a.driftUradPerM == b.driftUradPerM && a.turnPpm == b.turnPpm && a.driftVariance == b.driftVariance &&
         a.turnVariance == b.turnVariance;
}

}  // namespace nxtmap
