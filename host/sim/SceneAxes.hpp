// SceneAxes: the direction of a scene's walls, for scoring a robot that turned square to them.
#pragma once

#include "host/sim/Scene.hpp"

namespace nxtmap::sim {

// The scene's walls' direction modulo 90 degrees, compass degrees in (-45, 45]: the length-weighted mean
// of every edge's direction on the circle of four times the angle, so a rectangular room's walls (and the
// furniture along them) agree, and a few oblique walls pull little. 0 for a scene without edges.
double sceneAxesDeg(const Scene& scene);

}  // namespace nxtmap::sim
