#include "host/mapping/SquaredGrid.hpp"

#include <cmath>

#include "host/mapping/FrameTransform.hpp"
#include "host/sim/SceneAxes.hpp"
#include "host/sim/StartJitter.hpp"

namespace nxtmap::mapping {
namespace {
constexpr double kDroveOffCm = 5.0;
}  // namespace

SquaredGrid squaredGrid(const sim::SimRobot& robot, const Pilot& pilot, Dir explorerHeading,
                        sim::Heading setDownHeading, const sim::Vec2& setDownCm) {
  SquaredGrid g;
  // The walls' axis nearest to where the robot now faces: the frame it believes it maps in; with no straight
  // wall seen, the frame it was set down in (turned back to where it was set down).
  const double heading = robot.headingDeg();
  const double off = std::remainder(heading - sim::sceneAxesDeg(robot.scene()), 90.0);
  g.found = pilot.squaring().result().found;
  const double axis = g.found ? heading - off : robot.frame().headingDeg + 90.0 * static_cast<int>(setDownHeading);
  if (g.found) {
    g.offDeg = std::fabs(off);
    g.turnedDeg = off;
  }
  g.heading = static_cast<sim::Heading>(sim::squareQuarter(axis));
  const double turn = sim::squareRemainderDeg(axis);
  // The cell's centre where the pilot believes it: off the robot by the offset the nearest walls gave it.
  const PoseTracker& tracker = pilot.tracker();
  const double forwardCm = tracker.along(explorerHeading) / 10.0;
  const double rightCm = tracker.along(rotate(explorerHeading, 1)) / 10.0;
  const sim::Vec2 centre = believedCellCentre(sim::Vec2(robot.xCm(), robot.yCm()), axis, forwardCm, rightCm);
  // Turning on the spot leaves the centre within a few mm of where it was; an approach drives 20 cm or more.
  const bool droveOff = std::hypot(robot.xCm() - setDownCm.x(), robot.yCm() - setDownCm.y()) > kDroveOffCm;
  g.moved = !(g.heading == setDownHeading && std::fabs(turn - robot.frame().headingDeg) < 1e-6 && forwardCm == 0.0 &&
              rightCm == 0.0 && !droveOff);
  if (g.moved) g.placement = sim::placeOnGrid(robot.scene(), centre, turn, robot.frame().cellCm);
  return g;
}

BelievedGrid believedGrid(const sim::SimRobot& robot, const Pilot& pilot, const Pose& explorer) {
  const PoseTracker& tracker = pilot.tracker();
  // The compass heading the robot believes it faces along the explorer's heading, and that of the explorer's north.
  const double facingDeg = robot.headingDeg() - tracker.thetaMrad() * 0.18 / 3.14159265358979323846;
  const double northDeg = facingDeg - 90.0 * static_cast<int>(explorer.heading);
  const double forwardCm = tracker.along(explorer.heading) / 10.0;
  const double rightCm = tracker.along(rotate(explorer.heading, 1)) / 10.0;
  const sim::Vec2 centre = believedCellCentre(sim::Vec2(robot.xCm(), robot.yCm()), facingDeg, forwardCm, rightCm);
  BelievedGrid g;
  g.heading = static_cast<sim::Heading>(sim::squareQuarter(northDeg));
  g.placement = sim::placeOnGrid(robot.scene(), centre, sim::squareRemainderDeg(northDeg), robot.frame().cellCm);
  int col = 0, row = 0;
  FrameTransform(0, 0, g.heading).toWorld(explorer.cell, col, row);
  g.originCol = g.placement.startCol - col;
  g.originRow = g.placement.startRow - row;
  return g;
}

sim::Vec2 believedCellCentre(const sim::Vec2& robotCm, double axisDeg, double forwardCm, double rightCm) {
  const double rad = axisDeg * 3.14159265358979323846 / 180.0;
  const sim::Vec2 forward(std::sin(rad), -std::cos(rad)), right(std::cos(rad), std::sin(rad));
  return robotCm - forwardCm * forward - rightCm * right;
}

}  // namespace nxtmap::mapping
