// Site: a world as the simulator runs it, from any of the formats it reads (cli/SiteFiles loads them): its geometry (a Scene), the
// raster it was traced from (Moving AI and ROS maps, at their own resolution), and the world file's own
// start pose when it gives one. Independent of any robot: the robot's grid is laid on it by Placement.
#pragma once

#include "host/sim/Scene.hpp"
#include "host/sim/World.hpp"

#include <memory>
#include <optional>
#include <string>

namespace nxtmap::sim {

// A start pose in the plane: the robot's centre, cm, and its heading, compass degrees.
struct StartPose {
  Vec2 cm{0.0, 0.0};
  double headingDeg = 0.0;
};

struct Site {
  std::string name;                    // file stem
  std::shared_ptr<const Scene> scene;  // never null in a loaded site
  std::optional<World> raster;         // Moving AI / ROS source raster (its cells: cell (c, r) spans
                                       // c..c+1 x r..r+1 times its resolution in the plane)
  bool sceneIsRaster = false;          // the scene is the raster traced (so the raster is its own truth);
                                       // false for a HouseExpo plan, whose raster only names cells
  std::optional<StartPose> start;      // the world file's own start (nxtmap world files)

  // The centre of raster cell (col, row) facing heading: a start given as a cell of the raster.
  StartPose rasterStart(int col, int row, double headingDeg) const;
};

// A raster world as a site (tests, and worlds already loaded as rasters).
Site siteFromRaster(World raster);

}  // namespace nxtmap::sim
