// RobotDescription: the simulated robot as built. Its grid cell, its body, where its four sonars sit
// and what range it trusts: the robot's parameters, never the world's.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

// One ultrasonic sensor on the robot: its face `forwardCm` ahead of and `rightCm` to the right of the
// robot's centre, pointing `facingDeg` clockwise from the robot's heading (0 front, 90 right, ...).
struct SensorMount {
  double forwardCm = 0.0;
  double rightCm = 0.0;
  double facingDeg = 0.0;
};

struct RobotDescription {
  std::string name;                      // "published", "brick"
  int cellCm = 10;                       // the robot's grid cell, whole cm (the explorer's RangeGeometry::cellCm)
  double bodyLengthCm = 0.0;             // footprint along the heading, centred on the robot's centre; 0 = a point
  double bodyWidthCm = 0.0;              // footprint across the heading; 0 = a point
  std::array<SensorMount, 4> sensors{};  // front, right, back, left (SimRobot's sensor index)
  int mountCm = 0;                       // the explorer's RangeGeometry::mountCm (sensor face ahead of the centre)
  double minRangeM = 0.05;               // readings the robot trusts, metres (RangeGeometry::minCm)
  double rangeM = 1.0;                   // (RangeGeometry::maxCm)
  int faceMarginCm = 0;                  // where its map puts walls' faces (RangeGeometry::faceMarginCm)
  int echoMarginCm = 0;                  // how much nearer an echo marks its face (RangeGeometry::echoMarginCm)
  // Whether it takes its sonar's linear error (the noise profile's rangeScale and biasCm, as measured for the
  // sensor's kind) off every reading (RangeGeometry::scalePer10k, biasMm), as the brick's firmware does.
  bool correctsSonar = false;
  // The drive (the emulator's DriveModel and the wheel model): NXT 56 mm tyres, 112 mm track.
  double wheelDiameterCm = 5.6;
  double trackCm = 11.2;

  // The body's corners in the plane for a robot at (xCm, yCm) facing headingDeg; empty for a point.
  std::vector<std::array<double, 2>> footprint(double xCm, double yCm, double headingDeg) const;
  // How far the body's corners reach from its centre (cm; 0 for a point): what turning on the spot sweeps.
  double sweepRadiusCm() const;
  // Whether the body sweeps out of its own cell when it turns on the spot (ExplorerConfig::turnNeedsRoom).
  bool turnNeedsRoom() const { return 2.0 * sweepRadiusCm() > cellCm; }
};

// "published": the seed method's experiments: 10 cm cells, four sensors at the centre, 5 cm - 1 m trusted,
//   a point body (the published simulation has none; kept so the published figures reproduce).
// "brick": the NXT robot as firmware/app/BrickConfig.hpp builds it: 20 cm cells, sensors 6 cm out from the
//   centre, 7 cm - 1.2 m trusted, a 16 x 18 cm body.
std::optional<RobotDescription> robotByName(const std::string& name);
// The published robot with other cells and its sensors mountOffsetCm out along their axes: a raster world's
// own robot (its cells are the world's), as every run was before robots had descriptions.
RobotDescription pointRobotFor(int cellCm, double mountOffsetCm = 0.0);
std::vector<std::string> robotNames();

}  // namespace nxtmap::sim
