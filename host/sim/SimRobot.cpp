#include "host/sim/SimRobot.hpp"

#include "host/sim/RayCast.hpp"
#include "host/sim/SceneFromRaster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace nxtmap::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDriveCmPerS = 15.0;  // simulated clock only: the NXT robot's cruising speed, about
constexpr double kSpinDegPerS = 90.0;  // and its spin rate on the spot
constexpr double kSpinCheckDeg = 2.0;  // a spinning body is tested for contact every 2 degrees

double wrapDeg(double deg) {
  double h = std::fmod(deg, 360.0);
  if (h < 0.0) h += 360.0;
  if (h >= 360.0) h = 0.0;
  return h;
}

}  // namespace

SimRobot::SimRobot(std::shared_ptr<const Scene> scene, const RobotDescription& robot, const GridFrame& frame,
                   const Vec2& startCm, double headingDeg, const NoiseProfile& noise, uint64_t seed, double maxRangeCm)
    : scene_(std::move(scene)),
      robot_(robot),
      frame_(frame),
      noise_(noise),
      rng_(seed),
      sonar_(noise.sonar, maxRangeCm, seed),
      wheels_(noise.wheels, robot.wheelDiameterCm, robot.trackCm, seed),
      maxRangeCm_(maxRangeCm),
      x_(startCm.x()),
      y_(startCm.y()),
      heading_(wrapDeg(headingDeg)) {}

SimRobot::SimRobot(const World& world, int startCol, int startRow, Heading heading, const NoiseProfile& noise,
                   uint64_t seed, double maxRangeCm, double mountOffsetCm)
    : SimRobot(std::make_shared<const Scene>(traceRaster(world)),
               pointRobotFor(static_cast<int>(std::lround(world.resolutionM() * 100.0)), mountOffsetCm),
               GridFrame{Vec2(0.5 * world.resolutionM() * 100.0, 0.5 * world.resolutionM() * 100.0), 0.0,
                         world.resolutionM() * 100.0},
               Vec2((startCol + 0.5) * world.resolutionM() * 100.0, (startRow + 0.5) * world.resolutionM() * 100.0),
               headingToDeg(heading), noise, seed, maxRangeCm) {}

void SimRobot::setHeading(double deg) { heading_ = wrapDeg(deg); }

int SimRobot::col() const {
  int c = 0, r = 0;
  frame_.cellOf(Vec2(x_, y_), c, r);
  return c;
}

int SimRobot::row() const {
  int c = 0, r = 0;
  frame_.cellOf(Vec2(x_, y_), c, r);
  return r;
}

Heading SimRobot::nominalHeading() const {
  const long quarter = ((std::lround((heading_ - frame_.headingDeg) / 90.0) % 4) + 4) % 4;
  return static_cast<Heading>(quarter);
}

bool SimRobot::fits(double xCm, double yCm, double headingDeg) const {
  const auto corners = robot_.footprint(xCm, yCm, headingDeg);
  if (corners.empty()) return !scene_->solidAt(Vec2(xCm, yCm));
  std::vector<Vec2> body;
  body.reserve(corners.size());
  for (const auto& c : corners) body.emplace_back(c[0], c[1]);
  return !scene_->touches(body);
}

int SimRobot::ping(int sensor, bool othersFiring) {
  const int reading = pingAt(sensor, clockMs_, othersFiring);
  clockMs_ += SonarModel::kPingMs;
  return reading;
}

int SimRobot::pingAt(int sensor, double atMs, bool othersFiring) {
  ++rawPings_;
  if (sensor < 0 || sensor > 3) return kNoEcho;
  const SensorMount& m = robot_.sensors[static_cast<size_t>(sensor)];
  double fx = 0.0, fy = 0.0, rx = 0.0, ry = 0.0;
  directionVector(heading_, fx, fy);
  directionVector(heading_ + 90.0, rx, ry);
  const Vec2 face(x_ + m.forwardCm * fx + m.rightCm * rx, y_ + m.forwardCm * fy + m.rightCm * ry);
  return sonar_.ping(*scene_, face, heading_ + m.facingDeg, sensor, atMs, othersFiring, rng_);
}

MoveResult SimRobot::move(int cells) {
  const int dir = cells >= 0 ? 1 : -1;
  const int steps = std::abs(cells);
  for (int done = 0; done < steps; ++done) {
    const WheelStep step = wheels_.straight(dir * frame_.cellCm, rng_);
    if (!drive(step)) {
      // Bumped: the robot settles at the centre of the cell it is still in.
      int c = 0, r = 0;
      frame_.cellOf(Vec2(x_, y_), c, r);
      const Vec2 centre = frame_.toPlane(Vec2(c, r));
      x_ = centre.x();
      y_ = centre.y();
      return MoveResult{done * dir, true};
    }
  }
  return MoveResult{steps * dir, false};
}

bool SimRobot::setPose(double xCm, double yCm, double headingDeg) {
  if (!fits(xCm, yCm, headingDeg)) return false;
  x_ = xCm;
  y_ = yCm;
  setHeading(headingDeg);
  return true;
}

bool SimRobot::rotate(double deg) { return spin(wheels_.spin(deg, rng_)); }

void SimRobot::turn(int eighths) { spin(wheels_.turnEighths(eighths, rng_)); }

bool SimRobot::spin(const WheelStep& step) {
  const double deg = step.headingChangeDeg;
  clockMs_ += std::fabs(deg) / kSpinDegPerS * 1000.0;
  lastSpinShare_ = 1.0;
  lastSpinCountedDeg_ = step.countedDeg;
  if (robot_.footprint(x_, y_, heading_).empty()) {  // a point turns freely
    // (the wheels' part first, then the noise: the published runs' arithmetic, bit for bit)
    setHeading(heading_ + step.headingWheelsDeg + step.headingNoiseDeg);
    return true;
  }
  const int checks = std::max(1, static_cast<int>(std::ceil(std::fabs(deg) / kSpinCheckDeg)));
  double reached = heading_;
  for (int i = 1; i <= checks; ++i) {
    const double h = heading_ + deg * i / checks;
    if (!fits(x_, y_, h)) {  // the body meets an obstacle: the wheels stall part way
      lastSpinShare_ = static_cast<double>(i - 1) / checks;
      lastSpinCountedDeg_ = step.countedDeg * lastSpinShare_;
      setHeading(reached);
      return false;
    }
    reached = h;
  }
  setHeading(reached);
  return true;
}

bool SimRobot::drive(double cm) { return drive(wheels_.straight(cm, rng_)); }

bool SimRobot::drive(const WheelStep& step) {
  const double dist = step.distanceCm;
  clockMs_ += std::fabs(dist) / kDriveCmPerS * 1000.0;
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(dist))));  // 1 cm or finer
  double dx = 0.0, dy = 0.0;
  if (step.headingChangeDeg == 0.0) {
    // A straight line: every point is the start plus a fraction of one vector.
    directionVector(heading_, dx, dy);
    for (int i = 1; i <= steps; ++i) {
      const double f = dist * i / steps;
      if (!fits(x_ + f * dx, y_ + f * dy, heading_)) return false;
    }
    x_ += dist * dx;
    y_ += dist * dy;
    return true;
  }
  // An arc: the heading turns evenly along the way; each piece is driven along its mid heading.
  double x = x_, y = y_, h = heading_;
  const double piece = dist / steps, turnPiece = step.headingChangeDeg / steps;
  for (int i = 1; i <= steps; ++i) {
    directionVector(h + turnPiece / 2.0, dx, dy);
    x += piece * dx;
    y += piece * dy;
    h += turnPiece;
    if (!fits(x, y, h)) return false;
  }
  x_ = x;
  y_ = y;
  setHeading(h);
  return true;
}

}  // namespace nxtmap::sim
