// RoomCut: a room's map as the house keeps it, from everything its run saw. The run's map reaches
// through the doorways (the sonar sees beyond them); the room is the cells its start and the cells
// the robot stood in reach without crossing a doorway, their eight neighbours (its walls) and the
// doorways themselves.
#pragma once

#include <vector>

#include "common/grid/Cell.hpp"
#include "common/interpret/Doorway.hpp"
#include "common/interpret/RoomInterpretation.hpp"
#include "host/network/RoomMap.hpp"

namespace nxtmap::house {

// `full`: the run's map in the room's frame (start at 0,0); `doors`: the doorway cells (entrance
// and exits), held closed for the flood and kept in the cut; `stood`: cells the robot believed it
// stood in during the run (room frame; those not free in `full` are passed over).
network::RoomMap cutToRoom(const network::RoomMap& full, const std::vector<Cell>& doors,
                           const std::vector<Cell>& stood = {});

// The interpretation of a room's map (walls, size, exits) as the common core makes it of a grid.
RoomInterpretation interpretMap(const network::RoomMap& map, const RoomLimits& room, const DoorwayLimits& doorways);

}  // namespace nxtmap::house
