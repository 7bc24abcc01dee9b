#include "host/sim/RobotDescription.hpp"

#include <cmath>

namespace nxtmap::sim {

namespace {

// Four sensors facing front, right, back, left, each `outCm` from the centre along its own axis.
std::array<SensorMount, 4> mountsAlongAxes(double outCm) {
  return {SensorMount{outCm, 0.0, 0.0}, SensorMount{0.0, outCm, 90.0}, SensorMount{-outCm, 0.0, 180.0},
          SensorMount{0.0, -outCm, 270.0}};
}

RobotDescription published() {
  RobotDescription r;
  r.name = "published";
  r.cellCm = 10;
  r.sensors = mountsAlongAxes(0.0);
  r.mountCm = 0;
  r.minRangeM = 0.05;
  r.rangeM = 1.0;
  return r;
}

// firmware/app/BrickConfig.hpp: 200 mm cells, sensors 6 cm ahead of the centre, 7 cm .. 1.2 m trusted;
// firmware/drivers/MotionGeometry.hpp: 56 mm tyres, 112 mm track. The body: an NXT brick (about 14 x 9 cm)
// between two 56 mm wheels with four ultrasonic sensors on it: about 16 cm long, 18 cm wide over the tyres.
RobotDescription brick() {
  RobotDescription r;
  r.name = "brick";
  r.cellCm = 20;
  r.bodyLengthCm = 16.0;
  r.bodyWidthCm = 18.0;
  r.sensors = mountsAlongAxes(6.0);
  r.mountCm = 6;
  r.minRangeM = 0.07;
  r.rangeM = 1.2;
  r.faceMarginCm = 4;  // walls anywhere: as the brick (BrickConfig::faceMarginCm, echoMarginCm, measured there)
  r.echoMarginCm = 1;
  r.correctsSonar = true;
  return r;
}

}  // namespace

std::vector<std::array<double, 2>> RobotDescription::footprint(double xCm, double yCm, double headingDeg) const {
  if (bodyLengthCm <= 0.0 || bodyWidthCm <= 0.0) return {};
  const double rad = headingDeg * 3.14159265358979323846 / 180.0;
  const double fx = std::sin(rad), fy = -std::cos(rad);  // forward unit vector (compass heading)
  const double rx = std::cos(rad), ry = std::sin(rad);   // right unit vector
  const double hl = bodyLengthCm / 2.0, hw = bodyWidthCm / 2.0;
  std::vector<std::array<double, 2>> corners;
  for (const auto& [a, b] : {std::array<double, 2>{hl, hw}, {hl, -hw}, {-hl, -hw}, {-hl, hw}}) {
    corners.push_back({xCm + a * fx + b * rx, yCm + a * fy + b * ry});
  }
  return corners;
}

double RobotDescription::sweepRadiusCm() const {
  if (bodyLengthCm <= 0.0 || bodyWidthCm <= 0.0) return 0.0;
  return std::hypot(bodyLengthCm / 2.0, bodyWidthCm / 2.0);
}

std::optional<RobotDescription> robotByName(const std::string& name) {
  if (name == "published") return published();
  if (name == "brick") return brick();
  return std::nullopt;
}

RobotDescription pointRobotFor(int cellCm, double mountOffsetCm) {
  RobotDescription r = published();
  r.name = "point";
  r.cellCm = cellCm;
  r.sensors = mountsAlongAxes(mountOffsetCm);
  r.mountCm = static_cast<int>(std::lround(mountOffsetCm));
  return r;
}

std::vector<std::string> robotNames() { return {"published", "brick"}; }

}  // namespace nxtmap::sim
