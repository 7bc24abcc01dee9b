#include "host/emu/DriveModel.hpp"

#include "host/sim/RayCast.hpp"
#include "host/sim/WheelModel.hpp"

#include <algorithm>
#include <cmath>

namespace nxtmap::emu {

namespace {
constexpr double kQuarterDeg = 0.5;           // one quadrature state = half a degree
constexpr uint64_t kMaxStep = kMckHz / 2000;  // integrate motion in steps of at most 0.5 ms
constexpr double kPi = 3.14159265358979323846;
}  // namespace

DriveModel::DriveModel(Clock& clock, const AvrModel& avr, Pioa& pio, sim::SimRobot& robot, const DriveGeometry& g,
                       uint64_t seed)
    : clock_(clock), avr_(avr), pio_(pio), robot_(robot), geo_(g), rng_(seed ^ 0x5D1F7ULL) {
  publishPins();
}

double DriveModel::speed(int motor) const { return avr_.motorPower(motor) * geo_.degPerSecPerPercent; }

uint64_t DriveModel::nextEventAt() const {
  uint64_t next = kNever;
  for (int m = 0; m < 3; ++m) {
    const double v = speed(m);
    if (v == 0.0) continue;
    const double d = deg_[static_cast<size_t>(m)] / kQuarterDeg;
    const double toBoundary = (v > 0 ? std::floor(d) + 1.0 - d : d - std::ceil(d) + 1.0) * kQuarterDeg;
    const double seconds = toBoundary / std::fabs(v);
    const auto cycles = static_cast<uint64_t>(std::ceil(seconds * static_cast<double>(kMckHz)));
    next = std::min(next, last_ + std::clamp<uint64_t>(cycles, 1, kMaxStep));
  }
  return next;
}

void DriveModel::advanceTo(uint64_t now) {
  std::array<int, 3> power{avr_.motorPower(0), avr_.motorPower(1), avr_.motorPower(2)};
  sim::WheelModel& wheels = robot_.wheels();
  if (power != lastPower_) {
    lastPower_ = power;
    const int left = power[static_cast<size_t>(geo_.leftMotor)], right = power[static_cast<size_t>(geo_.rightMotor)];
    if (left == 0 && right == 0) {
      moving_ = false;
    } else if (!moving_) {  // setting off from rest: a new stretch
      moving_ = true;
      wheels.newStretch((left > 0 && right < 0) || (left < 0 && right > 0), rng_);
    }
  }
  while (last_ < now) {
    const uint64_t step = std::min(now - last_, kMaxStep);
    const double dt = static_cast<double>(step) / static_cast<double>(kMckHz);
    last_ += step;
    std::array<double, 3> d{};
    bool moving = false;
    for (int m = 0; m < 3; ++m) {
      d[static_cast<size_t>(m)] = speed(m) * dt;
      moving = moving || d[static_cast<size_t>(m)] != 0.0;
    }
    if (!moving) {
      last_ = now;
      break;
    }
    const sim::WheelModel before = wheels;  // a stall leaves the gear play where it was
    double dl = 0.0, dr = 0.0;
    wheels.arcs(d[static_cast<size_t>(geo_.leftMotor)], d[static_cast<size_t>(geo_.rightMotor)], dl, dr);
    const double ds = (dl + dr) / 2.0;
    const double wheelsDeg = (dl - dr) / wheels.trackCm() * 180.0 / kPi;  // clockwise positive
    const double dHeading = wheelsDeg + wheels.stretchTurnNoiseDeg(wheelsDeg);
    const double midHeading = robot_.headingDeg() + dHeading / 2.0;
    double dx = 0.0, dy = 0.0;
    sim::directionVector(midHeading, dx, dy);
    if (robot_.setPose(robot_.xCm() + ds * dx, robot_.yCm() + ds * dy, robot_.headingDeg() + dHeading)) {
      for (size_t m = 0; m < 3; ++m) deg_[m] += d[m];
      drivenCm_ += std::fabs(ds);
    } else {
      wheels = before;
      ++stalls_;  // bumped: the driven wheels do not turn
      for (int m = 0; m < 3; ++m)
        if (m != geo_.leftMotor && m != geo_.rightMotor) deg_[static_cast<size_t>(m)] += d[static_cast<size_t>(m)];
    }
  }
  last_ = std::max(last_, now);
  publishPins();
}

void DriveModel::publishPins() {
  uint32_t mask = 0, values = 0;
  for (size_t m = 0; m < 3; ++m) {
    const auto q = static_cast<long long>(std::floor(deg_[m] / kQuarterDeg));
    const int s = static_cast<int>(((q % 4) + 4) % 4);  // 0:(0,0) 1:(1,0) 2:(1,1) 3:(0,1) forward
    const bool pulse = s == 1 || s == 2;
    const bool dir = s == 2 || s == 3;
    mask |= (1u << kPulsePin[m]) | (1u << kDirPin[m]);
    if (pulse) values |= 1u << kPulsePin[m];
    if (dir) values |= 1u << kDirPin[m];
  }
  pio_.driveExternal(mask, values);
}

}  // namespace nxtmap::emu
