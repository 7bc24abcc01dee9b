#include "common/sensing/WallDirection.hpp"

#include "common/math/IntAbs.hpp"

namespace nxtmap {
namespace {

constexpr int32_t kWindowMrad = 436;  // a dip's floor is the lowest reading within 25 deg either side

// How far above its floor a dip's flanks are cut (cm): 10 % of the range, at least 3 cm.
constexpr int16_t tolerance(int16_t floorCm) { return static_cast<int16_t>(floorCm / 10 > 3 ? floorCm / 10 : 3); }

// v modulo a quarter turn, in [-785, 785].
constexpr int32_t wrapQuarter(int32_t v) {
  const int32_t q = WallDirection::kQuarterMrad;
  int32_t r = ((v % q) + q) % q;
  return r > q / 2 ? r - q : r;
}

// v modulo a full turn, in (-2 kQuarterMrad, 2 kQuarterMrad].
constexpr int32_t wrapHalfTurn(int32_t v) {
  const int32_t full = 4 * WallDirection::kQuarterMrad;
  while (v > full / 2) v -= full;
  while (v <= -full / 2) v += full;
  return v;
}

// The dips' bearings from the sweep's zero heading (a dip's centre plus its sensor's quarter turns).
constexpr int32_t bearing(const WallDirection::Dip& d) {
  return wrapHalfTurn(d.centreMrad + static_cast<int32_t>(d.sensor) * WallDirection::kQuarterMrad);
}

// v, but at least floor, within an int16_t (a cone up to 600 mrad: at most 1576).
constexpr int16_t atLeast(int32_t v, int32_t floor) {
  return static_cast<int16_t>(v > 30000 ? 30000 : (v > floor ? v : floor));
}

}  // namespace

WallDirection::WallDirection(int32_t coneHalfMrad)
    : minDipMrad_(atLeast(2 * coneHalfMrad + 176, kMinDipMrad)),
      loneDipMrad_(atLeast(2 * coneHalfMrad + 376, kLoneDipMrad)),
      lastResortDipMrad_(atLeast(2 * coneHalfMrad + 261, kLoneDipMrad)) {}

bool WallDirection::addHeading(int32_t mrad) {
  if (steps_ >= kMaxSteps || mrad < -kMaxHeadingMrad || mrad > kMaxHeadingMrad) return false;
  if (steps_ > 0 && mrad <= heading_[steps_ - 1]) return false;
  heading_[steps_] = static_cast<int16_t>(mrad);
  for (uint8_t& c : cm_[steps_]) c = 0;
  ++steps_;
  return true;
}

void WallDirection::addReading(Sensor s, int16_t cm) {
  if (steps_ == 0) return;
  const uint8_t c = static_cast<uint8_t>(cm > 0 && cm <= kFarCm ? cm : 0);
  cm_[steps_ - 1][static_cast<int>(s)] = c;
  if (steps_ < 3) return;
  // The reading before, far below both its neighbours: a lone wild echo, read as the nearer neighbour.
  uint8_t& b = cm_[steps_ - 2][static_cast<int>(s)];
  const uint8_t a = cm_[steps_ - 3][static_cast<int>(s)], near = a < c ? a : c;
  if (b > 0 && b + kLoneDropCm + near / 10 < near && a > 0 && c > 0) b = near;
}

bool WallDirection::localMinimum(int s, int k) const {
  if (!valid(s, k)) return false;
  // The headings increase with the index: only the neighbours within the window either side count.
  for (int dir = -1; dir <= 1; dir += 2) {
    for (int j = k + dir; j >= 0 && j < steps_ && abs32(heading_[j] - heading_[k]) <= kWindowMrad; j += dir) {
      if (!valid(s, j)) continue;
      if (cm_[j][s] < cm_[k][s] || (j < k && cm_[j][s] == cm_[k][s])) return false;
    }
  }
  return true;
}

WallDirection::Flank WallDirection::flankTop(int s, int k, int dir) const {
  const int16_t floor = cm_[k][s];
  const int16_t full = static_cast<int16_t>(floor + tolerance(floor));
  const Flank rose{true, false, full}, cut{false, false, 0};
  int16_t top = floor;
  bool skipped = false;
  for (int j = k + dir; j >= 0 && j < steps_; j += dir) {
    if (!valid(s, j)) {
      const int n = j + dir;  // one missing echo is passed over; more end the flank (specular loss)
      if (n < 0 || n >= steps_) return cut;  // the sweep ends on it: the floor may go on past the end
      if (!skipped && valid(s, n)) {
        skipped = true;
        continue;
      }
      return rose;
    }
    skipped = false;
    const int16_t v = cm_[j][s];
    if (v > full) return v > full + floor / 16 + 4 ? cut : rose;  // a wall's flank rises slower than that
    if (v > top) top = v;
    if (v + kCornerDropCm < top) return Flank{true, true, top};  // past a corner: a nearer wall again
  }
  return cut;  // ran off the sweep below the level: the dip is cut off
}

int32_t WallDirection::crossing(int s, int k, int dir, int16_t level, int& lastInside) const {
  lastInside = k;
  bool skipped = false;
  for (int j = k + dir; j >= 0 && j < steps_; j += dir) {
    if (valid(s, j) && cm_[j][s] <= level) {
      lastInside = j;
      skipped = false;
      continue;
    }
    const int i = lastInside;
    if (!valid(s, j)) {
      const int n = j + dir;
      if (!skipped && n >= 0 && n < steps_ && valid(s, n) && cm_[n][s] <= level) {
        skipped = true;
        continue;
      }
      return (heading_[i] + heading_[j]) / 2;  // the flank ends half way to the missing echo
    }
    // Linear between the last reading inside and this one: where the flank passes the level.
    return heading_[i] + (heading_[j] - heading_[i]) * (level - cm_[i][s]) / (cm_[j][s] - cm_[i][s]);
  }
  return heading_[lastInside];  // not reached: flankTop saw the flank rise above the level first
}

int WallDirection::dips(Dip* out, int max) const {
  int n = 0;
  for (int s = 0; s < kSensorCount; ++s) {
    int covered = -1;  // indices up to here belong to a dip already looked at
    for (int k = 0; k < steps_ && n < max; ++k) {
      if (k <= covered || !localMinimum(s, k)) continue;
      const int16_t floor = cm_[k][s];
      const Flank l = flankTop(s, k, -1), r = flankTop(s, k, +1);
      int leftIndex = k, rightIndex = k;
      if (!l.ok || !r.ok) {
        crossing(s, k, +1, floor, rightIndex);
        covered = rightIndex;
        continue;
      }
      // Both flanks rise through the full level, or a corner limits it: three quarters of the lower one's rise.
      int16_t level = static_cast<int16_t>(floor + tolerance(floor));
      const Flank both[2] = {l, r};
      for (const Flank& f : both) {
        const int16_t cornerLevel = static_cast<int16_t>(floor + (f.topCm - floor) * 3 / 4);
        if (f.corner && cornerLevel < level) level = cornerLevel;
      }
      const int32_t left = crossing(s, k, -1, level, leftIndex);
      const int32_t right = crossing(s, k, +1, level, rightIndex);
      covered = rightIndex;
      const int32_t width = right - left;
      if (floor < kNearCm || level - floor < kMinRiseCm || width > kMaxDipMrad || width < minDipMrad_) continue;
      out[n++] = Dip{static_cast<Sensor>(s), (left + right) / 2, width, floor, !l.corner && !r.corner};
    }
  }
  return n;
}

int WallDirection::distinct(Dip* found, int n) {
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    bool seen = false;
    for (int j = 0; j < kept && !seen; ++j)
      seen = abs32(wrapHalfTurn(bearing(found[i]) - bearing(found[j]))) <= kAgreeMrad;
    if (!seen) found[kept++] = found[i];
  }
  return kept;
}

WallDirectionEstimate WallDirection::estimate() const {
  Dip found[kMaxDips];
  const int n = distinct(found, dips(found, kMaxDips));
  WallDirectionEstimate e;
  e.dips = static_cast<uint8_t>(n);
  int best = -1, bestCount = 0;
  for (int i = 0; i < n; ++i) {
    int count = 0;
    for (int j = 0; j < n; ++j) {
      if (abs32(wrapQuarter(found[j].centreMrad - found[i].centreMrad)) <= kAgreeMrad) ++count;
    }
    if (count > bestCount) {
      best = i;
      bestCount = count;
    }
  }
  const bool loneWall = n == 1 && found[0].clean && found[0].widthMrad >= loneDipMrad_;
  if (best < 0 || (bestCount < 2 && !loneWall)) return e;
  const int32_t ref = wrapQuarter(found[best].centreMrad);
  int32_t sum = 0;
  for (int j = 0; j < n; ++j) {
    const int32_t d = wrapQuarter(found[j].centreMrad - ref);
    if (abs32(d) <= kAgreeMrad) sum += d;
  }
  const int32_t mean = sum >= 0 ? (sum + bestCount / 2) / bestCount : -((-sum + bestCount / 2) / bestCount);
  e.found = true;
  e.mrad = wrapQuarter(ref + mean);
  e.agreeing = static_cast<uint8_t>(bestCount);
  return e;
}

WallDirectionEstimate WallDirection::widestWall() const {
  Dip found[kMaxDips];
  const int n = distinct(found, dips(found, kMaxDips));
  WallDirectionEstimate e;
  e.dips = static_cast<uint8_t>(n);
  int best = -1;
  for (int i = 0; i < n; ++i) {
    if (found[i].clean && found[i].widthMrad >= lastResortDipMrad_ &&
        (best < 0 || found[i].widthMrad > found[best].widthMrad))
      best = i;
  }
  if (best < 0) return e;
  e.found = true;
  e.mrad = wrapQuarter(found[best].centreMrad);
  e.agreeing = 1;
  return e;
}

}  // namespace nxtmap
