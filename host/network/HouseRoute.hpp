// HouseRoute: routes across rooms (method sections 3.6 and 5). First the room graph is searched
// over gateways (fewest gateways), then each room is planned on its own map with host/plan (A* by
// default; unknown cells are never used): from the start to the middle cell of the gateway into
// the next room, which is the next leg's start in that room's frame, and so on to the goal.
#pragma once

#include <string>
#include <vector>

#include "host/network/HouseNetwork.hpp"
#include "host/plan/Planner.hpp"

namespace nxtmap::network {

// A cell of one room, in the room's frame.
struct RoomPoint {
  int room = 0;
  Cell cell{};
};

// The path inside one room: room-frame cells, 8-connected (no corner cutting).
struct HouseLeg {
  int room = 0;
  std::vector<Cell> cells;
};

struct HouseRoute {
  bool found = false;
  std::string error;           // why not, when not found
  std::vector<int> rooms;      // rooms passed, start room first
  std::vector<HouseLeg> legs;  // one per room
  double length = 0.0;         // cells (straight 1, diagonal sqrt(2))
  uint64_t nodesExpanded = 0;  // summed over the legs
  // The route as house-frame cells (consecutive legs share the gateway cell once).
  std::vector<Cell> houseCells(const HouseNetwork& house) const;
};

// Goal `to`; when nearLabel is set, `to` is ignored and the goal is the reachable cell next to the
// label's cell nearest the entry of the label's room (the first room holding that label).
HouseRoute planHouseRoute(const HouseNetwork& house, RoomPoint from, RoomPoint to,
                          plan::Algorithm algorithm = plan::Algorithm::AStar, const std::string& nearLabel = "");

// The room holding `label` (first in room order) and its cell; false when no room has it.
bool findLabel(const HouseNetwork& house, const std::string& label, RoomPoint& out);

}  // namespace nxtmap::network
