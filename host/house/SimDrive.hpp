// SimDrive: carries out one pilot action on the simulated robot (read: filtered samples; rotate;
// drive), exactly as MappingRun does, for the house's room runs and travels.
#pragma once

#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"
#include "common/sensing/RangeGeometry.hpp"
#include "host/sim/SimRobot.hpp"

namespace nxtmap::house {

DriveEvent carryOutOnRobot(sim::SimRobot& robot, const DriveAction& a, const RangeGeometry& geometry);

}  // namespace nxtmap::house
