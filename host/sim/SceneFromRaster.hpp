// SceneFromRaster: a raster World traced into the rings of a Scene, exactly, so that the scene answers as
// the raster does: Scene::cast from a point inside a free cell meets the same face at the same distance and
// incidence as castRay (RayCast.hpp), and Scene::solidAt(p) is World::blocked of p's cell off the cell lines.
#pragma once

#include "host/sim/Scene.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::sim {

// Every boundary between a blocked and a free cell (cells outside the map count as blocked, so the map's
// border around free cells is one) becomes ring sides, surface Hard; collinear unit faces are merged into
// one side. Plane coordinates: x = col * cellCm, y = row * cellCm with cellCm = resolutionM * 100. Each ring
// keeps free cells on its left as seen in the plane (x right, y down); where two blocked cells meet only
// at a corner the rings touch there without crossing. The scene is finished (its index built).
// Cost: O(cells) time, memory O(boundary faces).
Scene traceRaster(const World& world);

}  // namespace nxtmap::sim
