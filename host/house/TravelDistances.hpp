// TravelDistances: how far (in moves) each cell of the house's known map is from where the robot
// stands, for choosing the nearest exit to map next.
#pragma once

#include <vector>

#include "common/grid/Cell.hpp"
#include "host/network/RoomMap.hpp"

namespace nxtmap::house {

// Breadth-first distances (4-connected, over free cells of `known`) from `from`, indexed
// (y - minY) * width + (x - minX); -1 = not reached. `from` is where the robot stands: the start
// even when a room map overlapping there holds it as a wall (a room mapped a cell off). All -1
// when `from` lies outside the map.
std::vector<int> travelDistances(const network::RoomMap& known, Cell from);

}  // namespace nxtmap::house
