// RayCast: exact grid traversal (Amanatides-Woo DDA) of one ray through a World, in centimetres.
// Plane coordinates: x = col * cellCm (right), y = row * cellCm (DOWN); directions in degrees clockwise from
// north (0 = towards row 0, 90 = towards larger col).
#pragma once

#include "host/sim/World.hpp"

namespace nxtmap::sim {

struct RayHit {
  bool hit = false;           // false: nothing blocked within the range
  double distanceCm = 0.0;    // from the ray's origin to the first blocked-cell face, cm (0 if inside one)
  double incidenceDeg = 0.0;  // 0..90, angle between the ray and the hit face's normal
};

// Unit vector of a compass direction; exact (0 / +-1) for multiples of 90 degrees.
void directionVector(double deg, double& dx, double& dy);

// First blocked cell (cells outside the map count as blocked) hit by the ray from (xCm, yCm) towards deg,
// no farther than maxCm.
RayHit castRay(const World& world, double cellCm, double xCm, double yCm, double deg, double maxCm);

}  // namespace nxtmap::sim
