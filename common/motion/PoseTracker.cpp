#include "common/motion/PoseTracker.hpp"

#include "common/math/IntAbs.hpp"
#include "common/math/IntRound.hpp"

namespace nxtmap {
namespace {
constexpr int64_t kQuarterMrad = 1571;     // pi/2 in mrad, rounded (variance scaling only)
constexpr int64_t kQuarterUrad = 1570796;  // pi/2 in microradians
}  // namespace

PoseTracker::PoseTracker(const PoseNoise& noise, const WheelCalibration& wheels) : noise_(noise) {
#ifndef NXTMAP_NO_START_SQUARING
  s_[kDrift] = divRound(wheels.driftUradPerM, 100);
  p_[kDrift][kDrift] = divRound(wheels.driftVariance, 10000);
  s_[kTurn] = divRound(wheels.turnPpm, 10);
  p_[kTurn][kTurn] = divRound(wheels.turnVariance, 100);
#else
  (void)wheels;
#endif
}

void PoseTracker::reset(int64_t thetaVarianceMrad2) {
  s_[0] = s_[1] = s_[2] = 0;
  residualUrad_ = 0;
  for (int i = 0; i < kStates; ++i)  // the pose is forgotten, what the wheels do is not
    for (int j = 0; j < kStates; ++j)
      if (i < 3 || j < 3) p_[i][j] = 0;
  refusedWide_[0] = refusedWide_[1] = 0;
  p_[2][2] = thetaVarianceMrad2 > 0 ? thetaVarianceMrad2 : 0;
}

WheelCalibration PoseTracker::wheels() const {
  WheelCalibration w;
#ifndef NXTMAP_NO_START_SQUARING
  w.driftUradPerM = static_cast<int32_t>(s_[kDrift] * 100);
  w.driftVariance = p_[kDrift][kDrift] * 10000;
  w.turnPpm = static_cast<int32_t>(s_[kTurn] * 10);
  w.turnVariance = p_[kTurn][kTurn] * 100;
#endif
  return w;
}

int32_t PoseTracker::takeTurnPpm() {
#ifndef NXTMAP_NO_START_SQUARING
  const int32_t ppm = static_cast<int32_t>(s_[kTurn] * 10);
  s_[kTurn] = 0;
  return ppm;
#else
  return 0;
#endif
}

void PoseTracker::knowTurn(int64_t variancePpm2) {
#ifndef NXTMAP_NO_START_SQUARING
  s_[kTurn] = 0;
  for (int i = 0; i < kStates; ++i) p_[i][kTurn] = p_[kTurn][i] = 0;
  p_[kTurn][kTurn] = divRound(variancePpm2, 100);
#else
  (void)variancePpm2;
#endif
}

int32_t PoseTracker::driftMrad(int32_t mm) const {
#ifndef NXTMAP_NO_START_SQUARING
  return static_cast<int32_t>(divRound(s_[kDrift] * mm, 10000));
#else
  (void)mm;
  return 0;
#endif
}

void PoseTracker::place(int32_t xMm, int32_t yMm) {
  s_[0] = xMm;
  s_[1] = yMm;
  if (xMm != 0) p_[0][0] += readingVariance();
  if (yMm != 0) p_[1][1] += readingVariance();
}

void PoseTracker::turnHeading(int64_t urad) {
  const int64_t delta = urad + residualUrad_;
  const int64_t whole = divRound(delta, 1000);
  s_[2] += whole;
  residualUrad_ = delta - whole * 1000;
}

void PoseTracker::propagate(const int64_t (&f)[kStates][kStates]) {
  int64_t m[kStates][kStates];  // F P, times kScale
  for (int i = 0; i < kStates; ++i)
    for (int j = 0; j < kStates; ++j) {
      int64_t sum = 0;
      for (int k = 0; k < kStates; ++k) sum += f[i][k] * p_[k][j];
      m[i][j] = sum;
    }
  for (int i = 0; i < kStates; ++i)
    for (int j = 0; j <= i; ++j) {
      int64_t sum = 0;
      for (int k = 0; k < kStates; ++k) sum += m[i][k] * f[j][k];
      p_[i][j] = p_[j][i] = divRound(sum, kScale * kScale);
    }
}

void PoseTracker::rotated(int32_t mrad, int quarters) {
  // The heading error changes by what was turned (with the turn error learnt) minus what is believed,
  // kept to the microradian so that thousands of quarter turns do not add up rounding.
  int64_t urad = static_cast<int64_t>(mrad) * 1000 - quarters * kQuarterUrad;
#ifndef NXTMAP_NO_START_SQUARING
  urad += divRound(static_cast<int64_t>(mrad) * s_[kTurn], 100);  // turn state: 10 ppm
  int64_t f[kStates][kStates] = {};
  for (int i = 0; i < kStates; ++i) f[i][i] = kScale;
  f[2][kTurn] = divRound(static_cast<int64_t>(mrad) * kScale, 100000);
  propagate(f);
#endif
  turnHeading(urad);
  // Turn error grows with the angle turned, with a floor for small corrections.
  int64_t scaled = abs64(mrad) * 1000 / kQuarterMrad;  // per mille of a quarter
  if (scaled < 250) scaled = 250;
  const int64_t sigma = divRound(noise_.turnMradPerQuarter * scaled, 1000);
  p_[2][2] += sigma * sigma;
}

void PoseTracker::drove(int32_t mm, Dir heading) {
  // In pieces of at most kPieceMm, so that the drift's curve and the products below stay small.
  constexpr int32_t kPieceMm = 500;
  while (mm > kPieceMm || mm < -kPieceMm) {
    const int32_t piece = mm > 0 ? kPieceMm : -kPieceMm;
    drovePiece(piece, heading);
    mm -= piece;
  }
  drovePiece(mm, heading);
}

void PoseTracker::drovePiece(int32_t mm, Dir heading) {
  // Forward unit f and right unit r (clockwise of f) of the believed heading.
  const int64_t fx = dx(heading), fy = dy(heading);
  const Dir right = rotate(heading, 1);
  const int64_t r[2] = {dx(right), dy(right)};
  const int64_t m = mm;
  // Displacement = mm * (f + theta/1000 * r), plus the drift's curve: drift * mm^2 / 2 across.
  int64_t side = divRound(m * s_[2], 1000);
  int64_t f[kStates][kStates] = {};
  for (int i = 0; i < kStates; ++i) f[i][i] = kScale;
  for (int i = 0; i < 2; ++i) f[i][2] = m * r[i] * kScale / 1000;
#ifndef NXTMAP_NO_START_SQUARING
  side += divRound(s_[kDrift] * m * m, 20000000);  // drift state: 0.1 mrad/m
  for (int i = 0; i < 2; ++i) f[i][kDrift] = divRound(m * m * r[i] * kScale, 20000000);
  f[2][kDrift] = divRound(m * kScale, 10000);
  turnHeading(s_[kDrift] * m / 10);
#endif
  s_[0] += m * fx + side * r[0];
  s_[1] += m * fy + side * r[1];
  propagate(f);
  // Process noise: slip along the track, heading picked up per cell (100 mm nominal).
  const int64_t slip = divRound(abs64(m) * noise_.slipPerMille, 1000);
  const int64_t slipVar = slip * slip;
  p_[0][0] += slipVar * fx * fx;
  p_[1][1] += slipVar * fy * fy;
  const int64_t drift = divRound(noise_.driveMradPerCell * abs64(m), 100);
  p_[2][2] += drift * drift;
}

void PoseTracker::rebase(Dir d, int cells, int32_t cellMm) {
  s_[0] -= static_cast<int64_t>(dx(d)) * cells * cellMm;
  s_[1] -= static_cast<int64_t>(dy(d)) * cells * cellMm;
}

bool PoseTracker::measure(Dir d, int32_t offsetMm, int32_t extraVarianceMm2, bool straightFace) {
  const int k = isVertical(d) ? 1 : 0;
  const int64_t s = isVertical(d) ? dy(d) : dx(d);  // +1 or -1
  const int64_t predicted = s * s_[k];
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
    refusedWide_[k] = 0;
    update(k, s, innovation, spread, false);
    return true;
  }
  refusedWide_[k] = 0;
  update(k, s, innovation, spread, true);
  return true;
}

void PoseTracker::update(int k, int64_t sign, int64_t innovation, int64_t spread, bool teach) {
  // In the measured sign convention the state component is sign * state[k]. A reading far from its
  // prediction (beyond 2 sigma, or taken through the wide gate) corrects the pose but does not teach the
  // wheels: they are only considered (Schmidt), so that one wall mistaken for another cannot bend what is
  // learnt for the rest of the run.
  const int learnt = teach && innovation * innovation <= 4 * spread ? kStates : 3;
  int64_t pk[kStates];
  for (int i = 0; i < kStates; ++i) pk[i] = p_[i][k];
  for (int i = 0; i < learnt; ++i) s_[i] += divRound(sign * pk[i] * innovation, spread);
#ifndef NXTMAP_NO_START_SQUARING
  // Within what any wheels do (WheelCalibration's ranges: 200 mrad/m, 10 %), whatever the readings said.
  s_[kDrift] = s_[kDrift] > 1999 ? 1999 : (s_[kDrift] < -1999 ? -1999 : s_[kDrift]);
  s_[kTurn] = s_[kTurn] > 9999 ? 9999 : (s_[kTurn] < -9999 ? -9999 : s_[kTurn]);
#endif
  for (int i = 0; i < kStates; ++i)
    for (int j = 0; j <= i; ++j)
      if (j < learnt) p_[i][j] = p_[j][i] = p_[i][j] - divRound(pk[i] * pk[j], spread);
  ++accepted_;
}

bool PoseTracker::measureHeading(int32_t thetaMrad, int32_t varianceMrad2) {
  const int64_t innovation = thetaMrad - s_[2];
  const int64_t spread = p_[2][2] + varianceMrad2;  // mrad^2
  if (spread <= 0 || innovation * innovation > 9 * spread) {
    ++rejected_;
    return false;
  }
  update(2, 1, innovation, spread, true);
  return true;
}

}  // namespace nxtmap
