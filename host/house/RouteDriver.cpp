#include "host/house/RouteDriver.hpp"

#include <cstdlib>

namespace nxtmap::house {
namespace {

bool stepTo(sim::SimRobot& robot, DriveResult& r, Dir d) {
  if (r.belief.heading != d) {
    int eighths = 4;
    if (rotate(r.belief.heading, 1) == d) eighths = 2;
    if (rotate(r.belief.heading, -1) == d) eighths = -2;
    robot.turn(eighths);
    r.turnEighths += std::abs(eighths);
    r.belief.heading = d;
  }
  if (robot.move(1).blocked) return false;
  ++r.cellsMoved;
  r.belief.cell = advance(r.belief.cell, d);
  return true;
}

}  // namespace

DriveResult driveRoute(sim::SimRobot& robot, Pose belief, const std::vector<Cell>& cells) {
  DriveResult r;
  r.belief = belief;
  for (size_t i = 1; i < cells.size(); ++i) {
    const int dx = cells[i].x - cells[i - 1].x, dy = cells[i].y - cells[i - 1].y;
    if (std::abs(dx) > 1 || std::abs(dy) > 1) return r;  // not a route
    if (dx != 0 && !stepTo(robot, r, dx > 0 ? Dir::East : Dir::West)) return r;
    if (dy != 0 && !stepTo(robot, r, dy > 0 ? Dir::North : Dir::South)) return r;
  }
  r.arrived = true;
  return r;
}

}  // namespace nxtmap::house
