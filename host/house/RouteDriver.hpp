// RouteDriver: drives the simulated robot along a route of house-frame cells (for example a
// network::HouseRoute), one cell at a time: a diagonal step becomes two straight moves (the
// route never cuts a corner, so both side cells are free). The robot's belief is dead reckoning.
#pragma once

#include <vector>

#include "common/explore/Pose.hpp"
#include "host/sim/SimRobot.hpp"

namespace nxtmap::house {

struct DriveResult {
  bool arrived = false;  // every step was carried out
  int cellsMoved = 0;
  int turnEighths = 0;
  Pose belief;  // where the robot believes it is at the end (house frame)
};

// `belief`: the robot's pose in the house frame at the route's first cell.
DriveResult driveRoute(sim::SimRobot& robot, Pose belief, const std::vector<Cell>& houseCells);

}  // namespace nxtmap::house
