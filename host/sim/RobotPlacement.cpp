#include "host/sim/RobotPlacement.hpp"

#include "host/sim/StartClearance.hpp"
#include "host/sim/StartJitter.hpp"

#include <cmath>

namespace nxtmap::sim {

namespace {

// A square start on a raster cell's centre with the raster's own cells; sets the start cell.
bool onRasterGrid(const Site& site, const RobotDescription& robot, const StartPose& start, int& col, int& row) {
  if (!site.raster || !site.sceneIsRaster || std::fabs(site.raster->resolutionM() * 100.0 - robot.cellCm) > 1e-9)
    return false;
  if (squareRemainderDeg(start.headingDeg) != 0.0) return false;
  const double cell = robot.cellCm;
  col = static_cast<int>(std::floor(start.cm.x() / cell));
  row = static_cast<int>(std::floor(start.cm.y() / cell));
  return std::fabs(start.cm.x() - (col + 0.5) * cell) < 1e-9 && std::fabs(start.cm.y() - (row + 0.5) * cell) < 1e-9 &&
         site.raster->inside(col, row);
}

}  // namespace

RobotPlacement placeRobot(const Site& site, const RobotDescription& robot, const StartPose& nominal,
                          double startJitterDeg, uint64_t seed) {
  ClearStart clear{jitterStart(nominal, robot.cellCm, startJitterDeg, seed), 0.0};
  if (robot.turnNeedsRoom()) clear = withRoomToTurn(*site.scene, clear.pose, robot.cellCm, robot.sweepRadiusCm() + 1.0);
  const StartPose& start = clear.pose;
  const Heading heading = static_cast<Heading>(squareQuarter(start.headingDeg));
  int col = 0, row = 0;
  if (onRasterGrid(site, robot, start, col, row)) {
    const double cell = robot.cellCm;
    Placement grid{GridFrame{Vec2(0.5 * cell, 0.5 * cell), 0.0, cell}, col, row, site.raster->width(),
                   site.raster->height()};
    return RobotPlacement{site.scene, robot, start, grid, *site.raster, heading, clear.movedCm};
  }
  const Placement grid = placeOnGrid(*site.scene, start.cm, squareRemainderDeg(start.headingDeg), robot.cellCm);
  World truth = rasterizeScene(*site.scene, grid.frame, grid.width, grid.height, site.name);
  return RobotPlacement{site.scene, robot, start, grid, std::move(truth), heading, clear.movedCm};
}

RobotPlacement placeRobot(const Site& site, const PlacementRequest& r) {
  const int rasterCm = site.raster ? static_cast<int>(std::lround(site.raster->resolutionM() * 100.0)) : 10;
  const RobotDescription robot = r.robot ? *r.robot : pointRobotFor(rasterCm, r.mountOffsetCm);
  const StartPose nominal = r.pose ? *r.pose : site.rasterStart(r.startCol, r.startRow, headingToDeg(r.heading));
  return placeRobot(site, robot, nominal, r.startJitterDeg, r.seed);
}

}  // namespace nxtmap::sim
