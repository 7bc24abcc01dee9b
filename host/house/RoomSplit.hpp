// RoomSplit: the method's room size limit (section 3.2): an open area larger than the maximum is
// several rooms. The room's map is cut into partsX x partsY rooms of equal slices of the interior
// found by the interpretation (common/interpret); neighbouring parts overlap by the cut line, and
// every run of free cells on a cut line becomes a gateway. The parts keep the room's frame.
#pragma once

#include <vector>

#include "common/interpret/RoomInterpretation.hpp"
#include "host/network/HouseNetwork.hpp"

namespace nxtmap::house {

struct RoomParts {
  std::vector<network::RoomMap> maps;  // row-major over (partX, partY); one map when no split
  struct Cut {
    int partA = 0, partB = 0;  // indices into maps
    std::vector<Cell> cells;   // a run of free cells on the cut line (room frame)
  };
  std::vector<Cut> cuts;
  // The part holding a room-frame cell (the first one whose box contains it), -1 for none.
  int partOf(Cell c) const;
};

RoomParts splitRoom(const network::RoomMap& map, const RoomInterpretation& interpretation);

}  // namespace nxtmap::house
