// RobotPlacement: a robot set down in a site. Where it really stands (the nominal start moved by the start
// jitter), the grid it believes in (its own cells, centred on where it stands, turned with it), and the
// truth drawn on that grid by the safe rule (TruthRaster). Every simulating runner starts from one.
#pragma once

#include "host/sim/Heading.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/Site.hpp"
#include "host/sim/TruthRaster.hpp"
#include "host/sim/World.hpp"

#include <cstdint>
#include <memory>
#include <optional>

namespace nxtmap::sim {

struct RobotPlacement {
  std::shared_ptr<const Scene> scene;
  RobotDescription robot;
  StartPose start;  // the true start pose
  Placement grid;   // the robot's grid over the whole scene; grid.startCol/startRow hold the start
  World truth;      // the truth on that grid
  Heading heading;  // the start heading against the grid (N, E, S, W)
  // How far a body that sweeps out of its cell was moved from where it was set down to have room to turn
  // (StartClearance): 0 not moved, < 0 no spot nearby had room (set down where asked).
  double startMovedCm = 0.0;
};

// A robot whose body sweeps out of its cell when it turns is set down with room to turn (withRoomToTurn: the
// jittered start moved by whole cells, +1 cm to spare). The robot's grid is the raster's own (and the raster itself the truth, cell numbers kept) when the site's
// scene is a raster of the robot's cells and the true start is square on one of its cell centres; otherwise the
// grid is laid over the scene from the true start (placeOnGrid) and the truth rasterised on it.
RobotPlacement placeRobot(const Site& site, const RobotDescription& robot, const StartPose& nominal,
                          double startJitterDeg, uint64_t seed);

// What a run's configuration asks for. No robot: a point robot of the raster's own cells (the published
// set-up; 10 cm without a raster) with its sensors mountOffsetCm out. No pose: the centre of raster cell
// (startCol, startRow) facing heading.
struct PlacementRequest {
  std::optional<RobotDescription> robot;
  std::optional<StartPose> pose;
  int startCol = 0, startRow = 0;
  Heading heading = Heading::N;
  double startJitterDeg = 0.0;
  uint64_t seed = 1;
  double mountOffsetCm = 0.0;
};
RobotPlacement placeRobot(const Site& site, const PlacementRequest& request);

}  // namespace nxtmap::sim
