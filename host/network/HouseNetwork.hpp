// HouseNetwork: the method's network of rooms (section 5). Nodes are room maps, each in its own
// frame with its transform into the house frame (room 0's frame); edges are gateways, each
// holding the two rooms it joins and the exit's cells in each room's frame. Labels name cells
// of a room ("chair" -> room 2, cell (3, 4)).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/grid/Cell.hpp"
#include "host/network/RoomMap.hpp"
#include "host/network/RoomTransform.hpp"

namespace nxtmap::network {

struct RoomNode {
  std::string name;                    // unique, e.g. "room0"
  RoomMap map;                         // in the room's frame
  RoomTransform toHouse;               // room frame -> house frame
  std::map<std::string, Cell> labels;  // NAME -> cell in the room's frame
};

struct Gateway {
  int roomA = 0, roomB = 0;  // indices into rooms()
  std::vector<Cell> cellsA;  // the exit's cells in room A's frame
  std::vector<Cell> cellsB;  // the same cells in room B's frame
};

class HouseNetwork {
 public:
  // Returns the new room's index.
  int addRoom(RoomNode room);
  void addGateway(Gateway g);

  const std::vector<RoomNode>& rooms() const { return rooms_; }
  std::vector<RoomNode>& rooms() { return rooms_; }
  const std::vector<Gateway>& gateways() const { return gateways_; }
  int roomIndex(const std::string& name) const;  // -1 when absent

  // Checks the network: unique non-empty room names; the bounds of HouseLimits (room count, every
  // room's box and to_house within the coordinate range, all maps' cells, the house frame's extent);
  // labels inside their room's map; gateways joining two different existing rooms with the same
  // non-zero number of cells on each side, every gateway cell within kGatewayReachCells of its
  // room's map and free or unknown there. False with a message naming the first problem. A room
  // whose map has no cells yet counts as the one cell (minX, minY), as a house file holds it.
  bool validate(std::string& error) const;

  // The rooms to pass from `from` to `to` (both included) over gateways, fewest gateways first;
  // empty when `to` cannot be reached.
  std::vector<int> roomRoute(int from, int to) const;
  // Gateways joining rooms a and b (either order), in insertion order.
  std::vector<int> gatewaysBetween(int a, int b) const;

  // The whole house in the house frame: per cell, the state most rooms that know it agree on
  // (occupied wins ties); unknown where no room knows the cell.
  RoomMap merged() const;

 private:
  std::vector<RoomNode> rooms_;
  std::vector<Gateway> gateways_;
};

}  // namespace nxtmap::network
