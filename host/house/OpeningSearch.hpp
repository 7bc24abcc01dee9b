// OpeningSearch: unexplored space the room runs' exits missed. A doorway that was never recognised
// as one (seen at a slant, half mapped, its jambs off by a cell under noise) leaves a mapped room
// open onto unknown cells. Such an opening is a straight run of at least `minWidth` free cells of a
// room's map, each with nothing but unknown cells straight beyond it for `depth` cells in everything
// the house knows: deep enough to hold a room, too wide for a sensing hole.
#pragma once

#include <optional>
#include <vector>

#include "common/grid/Cell.hpp"
#include "common/protocol/HouseMessages.hpp"
#include "host/network/HouseNetwork.hpp"
#include "host/network/RoomMap.hpp"

namespace nxtmap::house {

struct Opening {
  int room = -1;             // the room whose free cells face the unknown
  std::vector<Cell> cells;   // the first unknown cells beyond, room frame (to cross; at most maxWidth)
  Cell inside{};             // the room's free cell in front of the middle, room frame
  Dir outward = Dir::North;  // towards the unknown, room frame
};

struct OpeningLimits {
  int minWidth = 4;  // cells side by side
  int depth = 6;     // unknown cells straight beyond each
  // The cells to cross, centred on the inside cell, at most: the widest doorway an EnterRoom holds.
  int maxWidth = protocol::kMaxDoorwayWidth;
};

// The widest opening of any room of `network` onto cells `known` (house frame) holds unknown,
// skipping those whose inside cell (house frame) is within 2 cells of one in `tried`; nullopt if none.
std::optional<Opening> findOpening(const network::HouseNetwork& network, const network::RoomMap& known,
                                   const std::vector<Cell>& tried, const OpeningLimits& limits = OpeningLimits{});

}  // namespace nxtmap::house
