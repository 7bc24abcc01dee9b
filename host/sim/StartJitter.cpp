#include "host/sim/StartJitter.hpp"

#include <cmath>
#include <random>

namespace nxtmap::sim {

namespace {
constexpr uint64_t kJitterStream = 0x51A27D0C4ULL;  // keeps the jitter apart from the robot's generator
constexpr double kInsideCell = 0.45;                // of a cell either side of the centre: inside the cell
constexpr double kPi = 3.14159265358979323846;
}  // namespace

StartPose jitterStart(const StartPose& nominal, double cellCm, double jitterDeg, uint64_t seed) {
  if (!(jitterDeg > 0.0)) return nominal;
  std::mt19937_64 rng(seed ^ kJitterStream);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double along = unit(rng) * kInsideCell * cellCm;
  const double across = unit(rng) * kInsideCell * cellCm;
  const double turn = unit(rng) * jitterDeg;
  const double rad = nominal.headingDeg * kPi / 180.0;
  const Vec2 forward(std::sin(rad), -std::cos(rad));
  const Vec2 right(std::cos(rad), std::sin(rad));
  return StartPose{nominal.cm + along * forward + across * right, nominal.headingDeg + turn};
}

int squareQuarter(double headingDeg) {
  const long q = std::lround(headingDeg / 90.0);
  return static_cast<int>(((q % 4) + 4) % 4);
}

double squareRemainderDeg(double headingDeg) {
  return headingDeg - 90.0 * static_cast<double>(std::lround(headingDeg / 90.0));
}

std::string startJitterProblem(double jitterDeg) {
  if (std::isfinite(jitterDeg) && jitterDeg >= 0.0 && jitterDeg <= kMaxStartJitterDeg) return "";
  return "--start-jitter must be 0 .. 45 degrees (0 = set down square on the cell centre)";
}

}  // namespace nxtmap::sim
