#include "host/sim/Site.hpp"

#include "host/sim/SceneFromRaster.hpp"

namespace nxtmap::sim {

StartPose Site::rasterStart(int col, int row, double headingDeg) const {
  const double cellCm = raster ? raster->resolutionM() * 100.0 : 0.0;
  return StartPose{Vec2((col + 0.5) * cellCm, (row + 0.5) * cellCm), headingDeg};
}

Site siteFromRaster(World raster) {
  Site site;
  site.name = raster.name();
  site.scene = std::make_shared<const Scene>(traceRaster(raster));
  site.raster = std::move(raster);
  site.sceneIsRaster = true;
  return site;
}

}  // namespace nxtmap::sim
