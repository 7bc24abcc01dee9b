#include "host/network/HouseRoute.hpp"

#include "host/network/HouseFiles.hpp"
#include "host/plan/NearGoal.hpp"
#include "host/plan/Traversability.hpp"

namespace nxtmap::network {
namespace {

plan::MapCell toMap(const RoomMap& m, Cell c) {
  plan::MapCell out;
  roomCellToMap(m, c, out.col, out.row);
  return out;
}

}  // namespace

std::vector<Cell> HouseRoute::houseCells(const HouseNetwork& house) const {
  std::vector<Cell> out;
  for (const HouseLeg& leg : legs) {
    const RoomTransform& t = house.rooms()[static_cast<size_t>(leg.room)].toHouse;
    for (const Cell c : leg.cells) {
      const Cell h = t.apply(c);
      if (out.empty() || out.back() != h) out.push_back(h);
    }
  }
  return out;
}

bool findLabel(const HouseNetwork& house, const std::string& label, RoomPoint& out) {
  for (size_t i = 0; i < house.rooms().size(); ++i) {
    const auto it = house.rooms()[i].labels.find(label);
    if (it == house.rooms()[i].labels.end()) continue;
    out.room = static_cast<int>(i);
    out.cell = it->second;
    return true;
  }
  return false;
}

HouseRoute planHouseRoute(const HouseNetwork& house, RoomPoint from, RoomPoint to, plan::Algorithm algorithm,
                          const std::string& nearLabel) {
  HouseRoute r;
  const int n = static_cast<int>(house.rooms().size());
  RoomPoint labelAt;
  if (!nearLabel.empty()) {
    if (!findLabel(house, nearLabel, labelAt)) {
      r.error = "no room has the label '" + nearLabel + "'";
      return r;
    }
    to.room = labelAt.room;
  }
  if (from.room < 0 || from.room >= n || to.room < 0 || to.room >= n) {
    r.error = "no such room";
    return r;
  }
  r.rooms = house.roomRoute(from.room, to.room);
  if (r.rooms.empty()) {
    r.error = "no gateways lead from " + house.rooms()[static_cast<size_t>(from.room)].name + " to " +
              house.rooms()[static_cast<size_t>(to.room)].name;
    return r;
  }
  std::unique_ptr<plan::Planner> planner = plan::makePlanner(algorithm);
  Cell at = from.cell;
  for (size_t i = 0; i < r.rooms.size(); ++i) {
    const int room = r.rooms[i];
    const RoomNode& node = house.rooms()[static_cast<size_t>(room)];
    const mapio::OccupancyMap map = toOccupancyMap(node.map, 0.1);
    const plan::Traversability grid(map);
    Cell goal;
    Cell nextStart{};
    const bool last = i + 1 == r.rooms.size();
    if (!last) {
      // The gateway into the next room whose middle cell is reachable; its cell in both frames.
      bool chosen = false;
      for (const int gi : house.gatewaysBetween(room, r.rooms[i + 1])) {
        const Gateway& g = house.gateways()[static_cast<size_t>(gi)];
        const bool aSide = g.roomA == room;
        const std::vector<Cell>& here = aSide ? g.cellsA : g.cellsB;
        const std::vector<Cell>& there = aSide ? g.cellsB : g.cellsA;
        const size_t mid = here.size() / 2;
        if (!grid.passable(toMap(node.map, here[mid]))) continue;
        goal = here[mid];
        nextStart = there[mid];
        chosen = true;
        break;
      }
      if (!chosen) {
        r.error =
            "no passable gateway from " + node.name + " to " + house.rooms()[static_cast<size_t>(r.rooms[i + 1])].name;
        return r;
      }
    } else if (!nearLabel.empty()) {
      const std::optional<plan::MapCell> near = plan::nearestCellNextTo(
          grid, toMap(node.map, at),
          mapio::CellBlock{toMap(node.map, labelAt.cell).col, toMap(node.map, labelAt.cell).row, 1, 1});
      if (!near) {
        r.error = "no free cell next to '" + nearLabel + "' can be reached in " + node.name;
        return r;
      }
      goal = mapCellToRoom(node.map, near->col, near->row);
    } else {
      goal = to.cell;
    }
    const plan::PlanResult p = planner->plan(grid, toMap(node.map, at), toMap(node.map, goal));
    r.nodesExpanded += p.nodesExpanded;
    if (!p.found()) {
      r.error = std::string("no path in ") + node.name + " (" + plan::statusName(p.status) + ")";
      return r;
    }
    HouseLeg leg;
    leg.room = room;
    for (const plan::MapCell& c : p.path) leg.cells.push_back(mapCellToRoom(node.map, c.col, c.row));
    r.length += p.length;
    r.legs.push_back(std::move(leg));
    at = nextStart;
  }
  r.found = true;
  return r;
}

}  // namespace nxtmap::network
