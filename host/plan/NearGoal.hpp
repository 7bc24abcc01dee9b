// NearGoal: goals given by labels. "go near the chair" (the method's future work, section 6.3): the
// closest reachable passable cell next to a labelled block of cells.
#pragma once

#include <optional>

#include "host/mapio/OccupancyMap.hpp"
#include "host/plan/Traversability.hpp"

namespace nxtmap::plan {

// Among the cells that touch the block (8-neighbours of its cells, outside the block) and are passable,
// the one with the shortest path from `from` (ties: smaller row, then smaller col). nullopt when none is
// reachable or `from` is not passable. If `from` already touches the block, that is `from` itself.
std::optional<MapCell> nearestCellNextTo(const Traversability& grid, MapCell from, const mapio::CellBlock& block);

}  // namespace nxtmap::plan
