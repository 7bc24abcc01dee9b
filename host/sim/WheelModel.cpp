#include "host/sim/WheelModel.hpp"

#include <algorithm>
#include <cmath>

namespace nxtmap::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;

// splitmix64: a fixed scramble of the seed, so a robot's systematic signs depend on the seed alone.
uint64_t mix(uint64_t z) {
  z += 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double gaussian(double sigma, std::mt19937_64& rng) {
  if (sigma <= 0.0) return 0.0;
  return std::normal_distribution<double>(0.0, sigma)(rng);
}

}  // namespace

WheelModel::WheelModel(const WheelNoise& noise, double wheelDiameterCm, double trackCm, uint64_t seed)
    : noise_(noise), cmPerDeg_(kPi * wheelDiameterCm / 360.0), trackCm_(trackCm) {
  const uint64_t signs = mix(seed ^ 0xEDEB0000ULL);
  const double edSign = (signs & 1u) != 0 ? 1.0 : -1.0;
  const double ebSign = (signs & 2u) != 0 ? 1.0 : -1.0;
  const double half = edSign * noise_.diameterRatioError / 2.0;
  diameter_ = {1.0 - half, 1.0 + half};
  trackRatio_ = 1.0 + ebSign * noise_.trackError;
  // Set down and pushed forward: both gear trains start engaged for forward motion.
  play_.fill(noise_.backlashDeg / 2.0);
}

double WheelModel::diameterRatio() const { return diameter_[1] / diameter_[0]; }

double WheelModel::systematicTurnError() const {
  return (diameter_[0] + diameter_[1]) / 2.0 / trackRatio_ - 1.0;  // as turnBy() turns
}

double WheelModel::systematicDriftRadPerM() const {
  return (diameter_[0] - diameter_[1]) * 100.0 / trackCm();  // as straight() curves
}

double WheelModel::throughPlay(int wheel, double motorDeg) {
  const double half = noise_.backlashDeg / 2.0;
  if (half <= 0.0) return motorDeg;
  double& p = play_[static_cast<size_t>(wheel)];
  const double moved = p + motorDeg;
  p = std::clamp(moved, -half, half);
  return moved - p;  // what the play could not absorb turns the wheel
}

double WheelModel::achieved(int wheel, double motorDeg) {
  if (noise_.encoderDeg <= 0.0 && noise_.backlashDeg <= 0.0) return 1.0;
  if (motorDeg == 0.0) return 0.0;
  double counted = motorDeg;
  if (noise_.encoderDeg > 0.0) counted = std::round(motorDeg / noise_.encoderDeg) * noise_.encoderDeg;
  return throughPlay(wheel, counted) / motorDeg;
}

WheelStep WheelModel::straight(double cm, std::mt19937_64& rng) {
  const double motorDeg = cm / cmPerDeg_;
  const double left = achieved(0, motorDeg) * diameter_[0];
  const double right = achieved(1, motorDeg) * diameter_[1];
  const double slip = 1.0 + gaussian(noise_.slipSigma, rng);
  WheelStep s;
  s.distanceCm = cm * ((left + right) / 2.0) * slip;
  s.headingWheelsDeg = cm * (left - right) * slip / trackCm() * 180.0 / kPi;
  s.headingChangeDeg = s.headingWheelsDeg;
  return s;
}

WheelStep WheelModel::turnBy(double deg, double noiseSigma, std::mt19937_64& rng) {
  const double armCm = deg * kPi / 180.0 * trackCm_ / 2.0;  // each wheel's commanded arc, left forward
  const double motorDeg = armCm / cmPerDeg_;
  const double left = achieved(0, motorDeg) * diameter_[0];
  const double right = achieved(1, -motorDeg) * diameter_[1];
  WheelStep s;
  s.distanceCm = armCm * (left - right) / 2.0;
  s.headingWheelsDeg = deg * ((left + right) / 2.0) / trackRatio_;
  s.headingNoiseDeg = gaussian(noiseSigma, rng);
  s.headingChangeDeg = s.headingWheelsDeg + s.headingNoiseDeg;
  const double countedMotorDeg =
      noise_.encoderDeg > 0.0 ? std::round(motorDeg / noise_.encoderDeg) * noise_.encoderDeg : motorDeg;
  s.countedDeg = countedMotorDeg * cmPerDeg_ / (trackCm_ / 2.0) * 180.0 / kPi;
  return s;
}

WheelStep WheelModel::spin(double deg, std::mt19937_64& rng) {
  return turnBy(deg, noise_.turnSigmaDeg * std::max(0.25, std::abs(deg) / 90.0), rng);
}

WheelStep WheelModel::turnEighths(int eighths, std::mt19937_64& rng) {
  return turnBy(45.0 * eighths, noise_.turnSigmaDeg, rng);
}

void WheelModel::arcs(double leftEncDeg, double rightEncDeg, double& leftCm, double& rightCm) {
  leftCm = throughPlay(0, leftEncDeg) * cmPerDeg_ * diameter_[0] * slip_;
  rightCm = throughPlay(1, rightEncDeg) * cmPerDeg_ * diameter_[1] * slip_;
}

void WheelModel::newStretch(bool spin, std::mt19937_64& rng) {
  slip_ = !spin && noise_.slipSigma > 0.0 ? 1.0 + gaussian(noise_.slipSigma, rng) : 1.0;
  turnZ_ = spin && noise_.turnSigmaDeg > 0.0 ? gaussian(1.0, rng) : 0.0;
  stretchTurnDeg_ = 0.0;
  stretchNoiseDeg_ = 0.0;
}

double WheelModel::stretchTurnNoiseDeg(double nominalDeg) {
  if (turnZ_ == 0.0 || nominalDeg == 0.0) return 0.0;
  stretchTurnDeg_ += nominalDeg;
  const double total = turnZ_ * noise_.turnSigmaDeg * std::max(0.25, std::abs(stretchTurnDeg_) / 90.0);
  const double step = total - stretchNoiseDeg_;
  stretchNoiseDeg_ = total;
  return step;
}

}  // namespace nxtmap::sim
