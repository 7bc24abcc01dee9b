// SimDrive: the simulated robot as the common core sees it. Its sonar geometry on a world (cells of
// the world's resolution, the trusted range, and the sure range of the beam), and one pilot action
// carried out on it (read: filtered samples; rotate; drive), as the firmware's drivers would.
// Shared by single-room runs (MappingRun) and house runs.
#pragma once

#include "common/explore/ExplorerConfig.hpp"
#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"
#include "common/motion/PoseTracker.hpp"
#include "common/sensing/RangeGeometry.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/SonarNoise.hpp"
#include "host/sim/WheelNoise.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::mapping {

// Cells of the world's resolution, readings trusted in [minRangeM, rangeM]. A beam of half-angle
// beamHalfAngleDeg (0 = a ray) reaches beside the axis beyond (cell / 2) / tan(angle): farther
// echoes only prove the cells before them free (RangeGeometry::sureCm).
// mountCm: the sensors' faces ahead of the robot's centre (RangeGeometry::mountCm).
RangeGeometry sonarGeometryFor(const sim::World& world, double minRangeM, double rangeM, double beamHalfAngleDeg,
                               int mountCm = 0);

// The sensor's blind zone as the robot knows its sonar (RangeGeometry::blindCm), whole cm: the near field
// where the modelled sensor returns no echo at all (0: none, as the published model).
int16_t sonarBlindCm(const sim::SonarNoise& sonar);

// The sonar's widest beam half-angle as the robot knows its sensor (PilotConfig::sonarConeMrad), mrad.
int16_t sonarConeMrad(const sim::SonarNoise& sonar);
// What a robot with these wheels holds in its store (PilotConfig::wheels): its systematic errors' sizes, not
// their values or signs (a real robot knows them from its last calibration, to about that accuracy), as the
// variances; the values 0. Wheels without systematic errors are stored as known to 0.1 deg/m and 0.1 %.
WheelCalibration storedCalibration(const sim::WheelNoise& wheels);
// The explorer's configuration for a simulated robot on `world`: its sonar geometry (beamHalfAngleDeg < 0:
// the sonar's cone; blindCm < 0: the sonar's blind zone; the sonar's linear error when the robot corrects it), its
// body's room to turn, and the search slices.
ExplorerConfig explorerConfigFor(const sim::World& world, const sim::RobotDescription& robot,
                                 const sim::SonarNoise& sonar, double minRangeM, double rangeM, double beamHalfAngleDeg,
                                 int blindCm, uint16_t searchSliceStates);

// othersFiring: every ping hears the other sensors pinging at the same moment (see RunConfig::sensorsTogether).
DriveEvent carryOutOnRobot(sim::SimRobot& robot, const DriveAction& a, const RangeGeometry& geometry,
                           bool othersFiring = false);

}  // namespace nxtmap::mapping
