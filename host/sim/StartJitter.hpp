// StartJitter: where a person actually sets the robot down. Nobody puts a robot exactly on a cell centre
// square to the walls: per seed, an offset inside the start cell and a heading misalignment.
#pragma once

#include "host/sim/Site.hpp"

#include <cstdint>
#include <string>

namespace nxtmap::sim {

constexpr double kDefaultStartJitterDeg = 10.0;  // --start-jitter without a value: +-10 degrees
constexpr double kMaxStartJitterDeg = 45.0;      // beyond 45 degrees "off square" has no meaning

// The true start for a nominal one: with jitterDeg > 0, the centre moved uniformly within the middle of
// the start cell (+-0.45 cell per axis along the nominal heading's axes, cellCm a side) and the heading
// turned uniformly within +-jitterDeg. Drawn from a generator of its own seeded by `seed`, so the robot's
// sonar and wheel draws are the same with and without jitter. jitterDeg <= 0: the nominal pose itself.
StartPose jitterStart(const StartPose& nominal, double cellCm, double jitterDeg, uint64_t seed);

// The robot's own square: the heading's nearest multiple of 90 degrees (0..3 = N, E, S, W) and the
// remainder, -45..45 degrees, by which the robot's grid is turned against the plane.
int squareQuarter(double headingDeg);
double squareRemainderDeg(double headingDeg);

// "" when d is a usable --start-jitter (0 .. kMaxStartJitterDeg, finite), else why not.
std::string startJitterProblem(double jitterDeg);

}  // namespace nxtmap::sim
