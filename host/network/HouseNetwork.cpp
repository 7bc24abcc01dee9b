#include "host/network/HouseNetwork.hpp"

#include <algorithm>
#include <deque>
#include <optional>
#include <set>
#include <string>
#include <tuple>

#include "host/mapio/OccupancyMap.hpp"
#include "host/network/CellBox.hpp"
#include "host/network/HouseLimits.hpp"

namespace nxtmap::network {

namespace {

// A room's box in its own frame: its map's box, or the one cell (minX, minY) for a map with no cells
// yet (a house file holds such a room as that one unknown cell).
CellBox roomBox(const RoomMap& m) {
  return CellBox{m.minX(), m.minY(), std::max(m.minX(), m.maxX()), std::max(m.minY(), m.maxY())};
}

// The room's box in the house frame. Precondition: the box's corners fit a Cell.
CellBox houseBox(const RoomNode& r) {
  const CellBox b = roomBox(r.map);
  const Cell lo = r.toHouse.apply(Cell{static_cast<int16_t>(b.minX), static_cast<int16_t>(b.minY)});
  const Cell hi = r.toHouse.apply(Cell{static_cast<int16_t>(b.maxX), static_cast<int16_t>(b.maxY)});
  return CellBox{std::min<int>(lo.x, hi.x), std::min<int>(lo.y, hi.y), std::max<int>(lo.x, hi.x),
                 std::max<int>(lo.y, hi.y)};
}

std::string cellText(Cell c) { return "[" + std::to_string(c.x) + ", " + std::to_string(c.y) + "]"; }

std::string boxText(const CellBox& b) {
  return "cells " + std::to_string(b.minX) + ".." + std::to_string(b.maxX) + " x " + std::to_string(b.minY) + ".." +
         std::to_string(b.maxY);
}

bool withinCoordinates(int v) { return v >= -kMaxCoordCells && v <= kMaxCoordCells; }

bool validNames(const std::vector<RoomNode>& rooms, std::string& error) {
  if (rooms.size() > static_cast<size_t>(kMaxRooms)) {
    error = std::to_string(rooms.size()) + " rooms, more than " + std::to_string(kMaxRooms);
    return false;
  }
  std::set<std::string> names;
  for (const RoomNode& r : rooms) {
    if (r.name.empty()) {
      error = "a room has no name";
      return false;
    }
    if (!names.insert(r.name).second) {
      error = "two rooms are named '" + r.name + "'";
      return false;
    }
  }
  return true;
}

// Each room's box and pose within the coordinate range, and all maps together within kMaxRoomCells.
bool validRooms(const std::vector<RoomNode>& rooms, std::string& error) {
  const std::string range = std::to_string(-kMaxCoordCells) + ".." + std::to_string(kMaxCoordCells);
  long cells = 0;
  for (const RoomNode& r : rooms) {
    const std::string which = "room '" + r.name + "'";
    const CellBox b = roomBox(r.map);
    if (!withinCoordinates(b.minX) || !withinCoordinates(b.minY) || !withinCoordinates(b.maxX) ||
        !withinCoordinates(b.maxY)) {
      error = which + ": its map (" + boxText(b) + ") reaches beyond cells " + range + " of the room's frame";
      return false;
    }
    if (!withinCoordinates(r.toHouse.x()) || !withinCoordinates(r.toHouse.y())) {
      error = which + ": to_house x, y (" + std::to_string(r.toHouse.x()) + ", " + std::to_string(r.toHouse.y()) +
              ") must lie within " + range + " cells";
      return false;
    }
    cells += static_cast<long>(r.map.width()) * r.map.height();
    if (cells > kMaxRoomCells) {
      error = "the room maps hold more than " + std::to_string(kMaxRoomCells) + " cells together";
      return false;
    }
  }
  return true;
}

// The rooms' boxes in the house frame span at most kMaxHouseSide cells a side. Precondition:
// validRooms (so every house-frame cell fits a Cell).
bool validExtent(const std::vector<RoomNode>& rooms, std::string& error) {
  if (rooms.empty()) return true;
  CellBox all = houseBox(rooms.front());
  for (const RoomNode& r : rooms) all = all.united(houseBox(r));
  if (all.width() > kMaxHouseSide || all.height() > kMaxHouseSide) {
    error = "the rooms span " + std::to_string(all.width()) + " x " + std::to_string(all.height()) +
            " cells in the house frame, more than " + std::to_string(kMaxHouseSide) +
            " a side (rooms placed too far apart: see their to_house and map origins)";
    return false;
  }
  return true;
}

bool validLabels(const std::vector<RoomNode>& rooms, std::string& error) {
  for (const RoomNode& r : rooms) {
    const CellBox b = roomBox(r.map);
    for (const auto& [name, c] : r.labels) {
      if (!mapio::OccupancyMap::validLabelName(name)) {
        error =
            "room '" + r.name + "': label name '" + name + "' is not 1-64 of A-Z a-z 0-9 _ - starting with a letter";
        return false;
      }
      if (!b.contains(c)) {
        error = "room '" + r.name + "': label '" + name + "' at " + cellText(c) + " lies outside the room's map (" +
                boxText(b) + ")";
        return false;
      }
    }
  }
  return true;
}

bool validGateways(const std::vector<RoomNode>& rooms, const std::vector<Gateway>& gateways, std::string& error) {
  const int n = static_cast<int>(rooms.size());
  for (size_t i = 0; i < gateways.size(); ++i) {
    const Gateway& g = gateways[i];
    const std::string which = "gateway " + std::to_string(i);
    if (g.roomA < 0 || g.roomA >= n || g.roomB < 0 || g.roomB >= n) {
      error = which + " names a room that does not exist";
      return false;
    }
    if (g.roomA == g.roomB) {
      error = which + " joins room '" + rooms[static_cast<size_t>(g.roomA)].name + "' to itself";
      return false;
    }
    if (g.cellsA.empty() || g.cellsA.size() != g.cellsB.size()) {
      error = which + " needs the same, non-zero number of cells on both sides";
      return false;
    }
    for (const auto& [room, cells, side] :
         {std::make_tuple(g.roomA, &g.cellsA, "cells_a"), std::make_tuple(g.roomB, &g.cellsB, "cells_b")}) {
      const RoomNode& r = rooms[static_cast<size_t>(room)];
      const CellBox near = roomBox(r.map).grown(kGatewayReachCells);
      for (const Cell c : *cells) {
        if (!near.contains(c)) {
          error = which + ": " + side + " " + cellText(c) + " lies outside room '" + r.name + "' (more than " +
                  std::to_string(kGatewayReachCells) + " cells from its map, " + boxText(roomBox(r.map)) + ")";
          return false;
        }
        if (r.map.at(c) == CellState::Occupied) {
          error = which + " has a cell that its room's map holds as a wall";
          return false;
        }
      }
    }
  }
  return true;
}

}  // namespace

int HouseNetwork::addRoom(RoomNode room) {
  rooms_.push_back(std::move(room));
  return static_cast<int>(rooms_.size()) - 1;
}

void HouseNetwork::addGateway(Gateway g) { gateways_.push_back(std::move(g)); }

int HouseNetwork::roomIndex(const std::string& name) const {
  for (size_t i = 0; i < rooms_.size(); ++i) {
    if (rooms_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

bool HouseNetwork::validate(std::string& error) const {
  return validNames(rooms_, error) && validRooms(rooms_, error) && validExtent(rooms_, error) &&
         validLabels(rooms_, error) && validGateways(rooms_, gateways_, error);
}

std::vector<int> HouseNetwork::roomRoute(int from, int to) const {
  const int n = static_cast<int>(rooms_.size());
  if (from < 0 || to < 0 || from >= n || to >= n) return {};
  std::vector<int> parent(static_cast<size_t>(n), -2);
  std::deque<int> queue{from};
  parent[static_cast<size_t>(from)] = -1;
  while (!queue.empty()) {
    const int r = queue.front();
    queue.pop_front();
    if (r == to) break;
    for (const Gateway& g : gateways_) {
      const int next = g.roomA == r ? g.roomB : (g.roomB == r ? g.roomA : -1);
      if (next < 0 || parent[static_cast<size_t>(next)] != -2) continue;
      parent[static_cast<size_t>(next)] = r;
      queue.push_back(next);
    }
  }
  if (parent[static_cast<size_t>(to)] == -2) return {};
  std::vector<int> route;
  for (int r = to; r != -1; r = parent[static_cast<size_t>(r)]) route.push_back(r);
  std::reverse(route.begin(), route.end());
  return route;
}

std::vector<int> HouseNetwork::gatewaysBetween(int a, int b) const {
  std::vector<int> out;
  for (size_t i = 0; i < gateways_.size(); ++i) {
    const Gateway& g = gateways_[i];
    if ((g.roomA == a && g.roomB == b) || (g.roomA == b && g.roomB == a)) out.push_back(static_cast<int>(i));
  }
  return out;
}

RoomMap HouseNetwork::merged() const {
  std::optional<CellBox> all;
  for (const RoomNode& r : rooms_) {
    if (r.map.width() == 0 || r.map.height() == 0) continue;
    all = all ? all->united(houseBox(r)) : houseBox(r);
  }
  if (!all) return RoomMap(0, 0, 0, 0);
  const int w = all->width(), h = all->height();
  const auto index = [&](Cell hc) {
    return static_cast<size_t>(hc.y - all->minY) * static_cast<size_t>(w) + static_cast<size_t>(hc.x - all->minX);
  };
  std::vector<int> freeVotes(static_cast<size_t>(w) * static_cast<size_t>(h), 0), occVotes(freeVotes.size(), 0);
  for (const RoomNode& r : rooms_) {
    const RoomMap& m = r.map;
    for (int y = m.minY(); y <= m.maxY(); ++y) {
      for (int x = m.minX(); x <= m.maxX(); ++x) {
        const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
        const CellState s = m.at(c);
        if (s == CellState::Unknown) continue;
        (s == CellState::Free ? freeVotes : occVotes)[index(r.toHouse.apply(c))]++;
      }
    }
  }
  RoomMap out(all->minX, all->minY, w, h);
  for (int y = all->minY; y <= all->maxY; ++y) {
    for (int x = all->minX; x <= all->maxX; ++x) {
      const Cell hc{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      const size_t i = index(hc);
      if (freeVotes[i] == 0 && occVotes[i] == 0) continue;
      out.set(hc, occVotes[i] >= freeVotes[i] ? CellState::Occupied : CellState::Free);
    }
  }
  return out;
}

}  // namespace nxtmap::network
