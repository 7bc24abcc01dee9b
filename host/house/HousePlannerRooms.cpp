// HousePlanner, recording the rooms: each mapped room cut to its doorways, registered to the house,
// split when too large, joined by gateways; exits into rooms already mapped; openings the exits missed.
#include <algorithm>
#include <cstdlib>
#include <string>

#include "host/house/HousePlanner.hpp"
#include "host/house/OpeningSearch.hpp"
#include "host/house/RoomCut.hpp"
#include "host/house/RoomRegistration.hpp"
#include "host/house/RoomSplit.hpp"
#include "host/log/Log.hpp"

namespace nxtmap::house {
namespace {

// How far (cells) a room's map is followed straight on from a doorway: past any room the brick maps.
constexpr int16_t kRoomRayCells = 64;

// Room `room`'s map, followed straight on along `out` from each of a doorway's cells (house frame), ends at one
// of its walls for most of them: the doorway opens into that room as mapped. Rays that run into unknown cells
// cross space the room only glimpsed from afar (through another opening, at the end of its range): not a room.
bool opensIntoMappedRoom(const network::RoomNode& room, const std::vector<Cell>& doorHouse, Dir out) {
  const network::RoomTransform toRoom = room.toHouse.inverse();
  int walled = 0;
  for (const Cell d : doorHouse) {
    for (int16_t k = 1; k <= kRoomRayCells; ++k) {
      const CellState s = room.map.at(toRoom.apply(advance(d, out, k)));
      if (s == CellState::Free) continue;
      if (s == CellState::Occupied) ++walled;
      break;
    }
  }
  return 2 * walled > static_cast<int>(doorHouse.size());
}

}  // namespace

void HousePlanner::recordRoom(const HouseReport& r, int fromRoom, const RoomExit* via,
                              const std::vector<Cell>& entranceHouse) {
  network::RoomTransform toHouse = network::RoomTransform::fromPose(belief_.cell, belief_.heading);
  const network::RoomTransform toRoom = toHouse.inverse();
  std::vector<Cell> entrance;
  for (const Cell c : entranceHouse) entrance.push_back(toRoom.apply(c));
  log::debug("house", "room %zu: pose %d,%d, exits %zu", network_.rooms().size(), r.pose.cell.x, r.pose.cell.y,
             r.exits.size());
  // The new room's frame came from the believed pose at its entrance; what it saw through the doorway
  // and of the walls it shares with the rooms already mapped re-registers it (and the belief with it).
  if (fromRoom >= 0 && config_.registerCells > 0) {
    const RoomRegistration reg = registerRoom(r.map, toHouse, network_.merged(), config_.registerCells);
    if (reg.shifted())
      log::debug("house", "  registered by %d,%d (score %d -> %d)", reg.dx, reg.dy, reg.scoreBefore, reg.scoreAfter);
    toHouse = reg.toHouse;
  }

  // The room: the cells reached from its start without crossing a doorway, and the doorways.
  std::vector<Cell> doors = entrance;
  for (const RoomExit& e : r.exits) {
    const std::vector<Cell> cells = cellsOf(e.door);
    doors.insert(doors.end(), cells.begin(), cells.end());
  }
  const network::RoomMap room = cutToRoom(r.map, doors, r.stood);
  // An open area larger than the maximum becomes several rooms (parts share the room's frame).
  const RoomParts parts = splitRoom(room, interpretMap(r.map, config_.roomLimits, config_.doorways));
  const int first = static_cast<int>(network_.rooms().size());
  for (const network::RoomMap& part : parts.maps) {
    network::RoomNode node;
    node.name = "room" + std::to_string(network_.rooms().size());
    node.map = part;
    node.toHouse = toHouse;
    network_.addRoom(std::move(node));
  }
  for (const RoomParts::Cut& cut : parts.cuts) {
    addPassableGateway(network::Gateway{first + cut.partA, first + cut.partB, cut.cells, cut.cells});
  }
  const auto partOf = [&](Cell at) { return first + std::max(0, parts.partOf(at)); };
  if (fromRoom >= 0 && via != nullptr && !entrance.empty()) {
    network::Gateway g;
    g.roomA = fromRoom;
    g.roomB = partOf(entrance[entrance.size() / 2]);
    g.cellsA = cellsOf(via->door);
    g.cellsB = entrance;
    addPassableGateway(std::move(g));
  }
  for (const RoomExit& e : r.exits) pending_.push_back(Pending{partOf(e.inside), e});
  network::RoomNode seen;
  seen.name = "run " + std::to_string(seen_.size());
  seen.map = r.map;
  seen.toHouse = toHouse;
  seen_.push_back(std::move(seen));
  exitsFound_ += static_cast<int>(r.exits.size());
  brickToHouse_ = toHouse;
  belief_ = Pose{toHouse.apply(r.pose.cell), toHouse.apply(r.pose.heading)};
}

void HousePlanner::addPassableGateway(network::Gateway g) {
  const auto& rooms = network_.rooms();
  const network::RoomMap& a = rooms[static_cast<size_t>(g.roomA)].map;
  const network::RoomMap& b = rooms[static_cast<size_t>(g.roomB)].map;
  network::Gateway kept{g.roomA, g.roomB, {}, {}};
  for (size_t i = 0; i < g.cellsA.size() && i < g.cellsB.size(); ++i) {
    if (a.at(g.cellsA[i]) == CellState::Occupied || b.at(g.cellsB[i]) == CellState::Occupied) continue;
    kept.cellsA.push_back(g.cellsA[i]);
    kept.cellsB.push_back(g.cellsB[i]);
  }
  if (kept.cellsA.size() < g.cellsA.size())
    log::debug("house", "  gateway %d-%d: %zu of %zu cells are a wall in a room's map, dropped", g.roomA, g.roomB,
               g.cellsA.size() - kept.cellsA.size(), g.cellsA.size());
  if (!kept.cellsA.empty()) network_.addGateway(std::move(kept));
}

bool HousePlanner::leadsToMappedRoom(const Pending& p) {
  const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(p.room)];
  const Cell inside = owner.toHouse.apply(p.exit.inside);
  const Dir out = owner.toHouse.apply(p.exit.outward);
  const auto& rooms = network_.rooms();
  const std::vector<Cell> cells = cellsOf(p.exit.door);
  for (int k = 1; k <= 2; ++k) {
    const Cell beyond = advance(inside, out, static_cast<int16_t>(p.exit.door.depth + k));
    for (size_t j = 0; j < rooms.size(); ++j) {
      if (static_cast<int>(j) == p.room) continue;
      const network::RoomTransform toJ = rooms[j].toHouse.inverse();
      if (!rooms[j].map.isFree(toJ.apply(beyond))) continue;
      std::vector<Cell> house, inJ;
      for (const Cell c : cells) {
        house.push_back(owner.toHouse.apply(c));
        inJ.push_back(toJ.apply(house.back()));
      }
      if (!opensIntoMappedRoom(rooms[j], house, out)) continue;
      // A gateway to a mapped room; skip it when that doorway is already a gateway of the two.
      // The same doorway seen from the other room may be found a cell wider or shifted.
      bool known = false;
      for (const int gi : network_.gatewaysBetween(p.room, static_cast<int>(j))) {
        const network::Gateway& g = network_.gateways()[static_cast<size_t>(gi)];
        for (const auto& [room, gcells] : {std::make_pair(g.roomA, &g.cellsA), std::make_pair(g.roomB, &g.cellsB)}) {
          const network::RoomNode& a = rooms[static_cast<size_t>(room)];
          for (const Cell gc : *gcells) {
            const Cell h = a.toHouse.apply(gc);
            for (const Cell hc : house) known = known || (std::abs(h.x - hc.x) + std::abs(h.y - hc.y) <= 2);
          }
        }
      }
      if (!known) addPassableGateway(network::Gateway{p.room, static_cast<int>(j), cells, inJ});
      return true;
    }
  }
  return false;
}

bool HousePlanner::queueOpening() {
  // No exit left: space the exits missed (a doorway never recognised) is explored through the
  // widest opening onto it, as if it were an exit.
  if (static_cast<int>(network_.rooms().size()) >= config_.maxRooms ||
      static_cast<int>(openingsTried_.size()) >= config_.maxOpenings)
    return false;
  const std::optional<Opening> o = findOpening(network_, knownForTravel(), openingsTried_);
  if (!o) return false;
  const network::RoomNode& owner = network_.rooms()[static_cast<size_t>(o->room)];
  openingsTried_.push_back(owner.toHouse.apply(o->inside));
  log::debug("house", "opening of room %d, %zu cells wide, at %d,%d", o->room, o->cells.size(), openingsTried_.back().x,
             openingsTried_.back().y);
  RoomExit e;
  e.door = doorwayAround(o->cells.data(), static_cast<int>(o->cells.size()));
  e.inside = o->inside;
  e.outward = o->outward;
  pending_.push_back(Pending{o->room, e});
  return true;
}

}  // namespace nxtmap::house
