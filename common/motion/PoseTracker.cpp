#include "common/motion/PoseTracker.hpp"

namespace nxtmap {
namespace {
constexpr int64_t kQuarterMrad = 1571;     // pi/2 in mrad, rounded (variance scaling only)
constexpr int64_t kQuarterUrad = 1570796;  // pi/2 in microradians
constexpr int64_t abs64(int64_t v) { return v < 0 ? -v : v; }
// Rounded division (ties away from zero); d > 0.
constexpr int64_t divRound(int64_t n, int64_t d) { return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d); }
}  // namespace

void PoseTracker::reset(int64_t thetaVarianceMrad2) {
  x_ = y_ = t_ = 0;
  residualUrad_ = 0;
  for (auto& row : p_)
    for (auto& v : row) v = 0;
  refusedWide_[0] = refusedWide_[1] = 0;
  p_[2][2] = thetaVarianceMrad2 > 0 ? thetaVarianceMrad2 : 0;
}

void PoseTracker::place(int32_t xMm, int32_t yMm) {
  x_ = xMm;
  y_ = yMm;
  if (xMm != 0) p_[0][0] += readingVariance();
  if (yMm != 0) p_[1][1] += readingVariance();
}

void PoseTracker::rotated(int32_t mrad, int quarters) {
  // The heading error changes by what was turned minus what is believed, kept to the microradian
  // so that thousands of quarter turns do not add up rounding.
  const int64_t delta = static_cast<int64_t>(mrad) * 1000 - quarters * kQuarterUrad + residualUrad_;
  const int64_t whole = divRound(delta, 1000);
  t_ += whole;
  residualUrad_ = delta - whole * 1000;
  // Turn error grows with the angle turned, with a floor for small corrections.
  int64_t scaled = abs64(mrad) * 1000 / kQuarterMrad;  // per mille of a quarter
  if (scaled < 250) scaled = 250;
  const int64_t sigma = divRound(noise_.turnMradPerQuarter * scaled, 1000);
  p_[2][2] += sigma * sigma;
}

void PoseTracker::drove(int32_t mm, Dir heading) {
  // Forward unit f and right unit r (clockwise of f) of the believed heading.
  const int64_t fx = dx(heading), fy = dy(heading);
  const Dir right = rotate(heading, 1);
  const int64_t rx = dx(right), ry = dy(right);
  // Displacement = mm * (f + theta/1000 * r).
  const int64_t side = divRound(static_cast<int64_t>(mm) * t_, 1000);
  x_ += mm * fx + side * rx;
  y_ += mm * fy + side * ry;
  // Covariance: F = I + a * e_theta in the position rows, a_i = mm * r_i / 1000.
  const int64_t a[2] = {mm * rx, mm * ry};  // x1000
  int64_t n[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) n[i][j] = p_[i][j];
  for (int i = 0; i < 2; ++i) {
    n[i][2] = p_[i][2] + divRound(a[i] * p_[2][2], 1000);
    n[2][i] = n[i][2];
  }
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      n[i][j] =
          p_[i][j] + divRound(a[i] * p_[2][j] + a[j] * p_[i][2], 1000) + divRound(a[i] * a[j] * p_[2][2], 1000000);
  // Process noise: slip along the track, heading picked up per cell (100 mm nominal).
  const int64_t slip = divRound(abs64(mm) * noise_.slipPerMille, 1000);
  const int64_t slipVar = slip * slip;
  n[0][0] += slipVar * fx * fx;
  n[1][1] += slipVar * fy * fy;
  const int64_t drift = divRound(noise_.driveMradPerCell * abs64(mm), 100);
  n[2][2] += drift * drift;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p_[i][j] = n[i][j];
}

void PoseTracker::rebase(Dir d, int cells, int32_t cellMm) {
  x_ -= static_cast<int64_t>(dx(d)) * cells * cellMm;
  y_ -= static_cast<int64_t>(dy(d)) * cells * cellMm;
}

bool PoseTracker::measure(Dir d, int32_t offsetMm, int32_t extraVarianceMm2, bool straightFace) {
  const int k = isVertical(d) ? 1 : 0;
  const int64_t s = isVertical(d) ? dy(d) : dx(d);  // +1 or -1
  const int64_t predicted = s * (k == 0 ? x_ : y_);
  const int64_t innovation = offsetMm - predicted;
  const int64_t r = static_cast<int64_t>(noise_.readingMm) * noise_.readingMm + extraVarianceMm2;
  int64_t spread = p_[k][k] + r;  // innovation variance, mm^2
  // Gate: within 3 sigma of the prediction and within the absolute gate; beyond that gate, a straight
  // wall face within 2 sigma and the wide gate.
  const int64_t size = abs64(innovation);
  const bool inGate =
      size <= noise_.gateMm || (straightFace && size <= noise_.wideGateMm && innovation * innovation <= 4 * spread);
  if (innovation * innovation > 9 * spread || !inGate) {
    // A straight face between the gates: taken when it confirms the last such refusal on this axis.
    const bool wide = noise_.confirmWide && straightFace && size > noise_.gateMm && size <= noise_.wideGateMm;
    const int8_t sign = s * innovation > 0 ? 1 : -1;
    if (!wide || refusedWide_[k] != sign) {
      if (wide) refusedWide_[k] = sign;
      ++rejected_;
      return false;
    }
    if (p_[k][k] < innovation * innovation) p_[k][k] = innovation * innovation;
    spread = p_[k][k] + r;
  }
  refusedWide_[k] = 0;
  // In the measured axis' sign convention the state component is s * state[k].
  int64_t pk[3];
  for (int i = 0; i < 3; ++i) pk[i] = p_[i][k];
  int64_t* state[3] = {&x_, &y_, &t_};
  for (int i = 0; i < 3; ++i) *state[i] += divRound(s * pk[i] * innovation, spread);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p_[i][j] -= divRound(pk[i] * pk[j], spread);
  ++accepted_;
  return true;
}

bool PoseTracker::measureHeading(int32_t thetaMrad, int32_t varianceMrad2) {
  const int64_t innovation = thetaMrad - t_;
  const int64_t spread = p_[2][2] + varianceMrad2;  // mrad^2
  if (spread <= 0 || innovation * innovation > 9 * spread) {
    ++rejected_;
    return false;
  }
  int64_t pk[3];
  for (int i = 0; i < 3; ++i) pk[i] = p_[i][2];
  int64_t* state[3] = {&x_, &y_, &t_};
  for (int i = 0; i < 3; ++i) *state[i] += divRound(pk[i] * innovation, spread);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p_[i][j] -= divRound(pk[i] * pk[j], spread);
  ++accepted_;
  return true;
}

}  // namespace nxtmap
