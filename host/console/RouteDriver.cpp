#include "host/console/RouteDriver.hpp"

#include <sstream>

#include "host/network/HouseFiles.hpp"

namespace nxtmap::console {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string cellText(Cell c) { return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")"; }

// A room by number (0..rooms-1) or name; -1 when there is none.
int roomOf(const network::HouseNetwork& h, const std::string& name) {
  if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos || name.size() > 5)
    return h.roomIndex(name);
  const int room = std::stoi(name);
  return room < static_cast<int>(h.rooms().size()) ? room : -1;
}

// The route's first line: the rooms it crosses, its gateways and its length.
std::string routeText(const network::HouseRoute& r, const network::HouseNetwork& h) {
  std::ostringstream o;
  const network::RoomNode& goalRoom = h.rooms()[static_cast<size_t>(r.rooms.back())];
  o << "route to room " << r.rooms.back() << " (" << goalRoom.name << ") " << cellText(r.legs.back().cells.back())
    << ": rooms";
  for (size_t i = 0; i < r.rooms.size(); ++i) o << (i ? " -> " : " ") << r.rooms[i];
  for (size_t i = 0; i + 1 < r.legs.size(); ++i) {
    o << (i ? ", " : "; gateways ") << cellText(r.legs[i].cells.back()) << " in room " << r.legs[i].room << " = "
      << cellText(r.legs[i + 1].cells.front()) << " in room " << r.legs[i + 1].room;
  }
  o.setf(std::ios::fixed);
  o.precision(1);
  o << "; " << r.length << " cells\n";
  return o.str();
}

}  // namespace

network::RoomPoint RouteDriver::target(const ConsoleCommand& c, const network::HouseNetwork& h,
                                       const std::string& what) const {
  const int room = roomOf(h, c.name);
  if (room < 0) {
    throw ConsoleError(what + ": no room '" + c.name + "' (the house has rooms 0.." +
                       std::to_string(h.rooms().size() - 1) + ", see rooms); nothing sent");
  }
  const network::RoomMap& m = h.rooms()[static_cast<size_t>(room)].map;
  if (c.col >= m.width() || c.row >= m.height()) {
    throw ConsoleError(what + ": outside room " + std::to_string(room) + "'s map (" + std::to_string(m.width()) +
                       " x " + std::to_string(m.height()) + " cells); nothing sent");
  }
  const Cell cell = network::mapCellToRoom(m, c.col, c.row);
  if (m.at(cell) == CellState::Occupied) throw ConsoleError(what + ": that cell is an obstacle; nothing sent");
  if (m.at(cell) == CellState::Unknown) throw ConsoleError(what + ": that cell is unexplored; nothing sent");
  return network::RoomPoint{room, cell};
}

void RouteDriver::checkRooms(const network::HouseRoute& r, const network::HouseNetwork& h,
                             const std::string& what) const {
  const int cap = runner_.with([](link::Session& s) { return s.hello() ? (1 << s.hello()->gridWidthLog2) : 64; });
  for (size_t i = 1; i < r.rooms.size(); ++i) {
    const int room = r.rooms[i];
    if (!house_.placed(room)) {
      throw ConsoleError(what + ": room " + std::to_string(room) + " is not connected to the house yet; nothing sent");
    }
    const network::RoomMap& m = h.rooms()[static_cast<size_t>(room)].map;
    if (m.width() > cap || m.height() > cap) {
      throw ConsoleError(what + ": room " + std::to_string(room) +
                         "'s map is larger than the brick holds; nothing sent");
    }
  }
}

std::string RouteDriver::start(const ConsoleCommand& c) {
  const std::string what =
      c.near ? "route near " + c.name : "route " + c.name + " " + std::to_string(c.col) + " " + std::to_string(c.row);
  if (!house_.liveValid()) throw ConsoleError(what + ": the brick has not taken this room's map yet; nothing sent");
  const network::HouseNetwork h = house_.snapshot();
  const std::optional<Pose> pose = runner_.with([](link::Session& s) { return s.pose(); });
  if (!pose) throw ConsoleError(what + ": the robot's position is not known yet; nothing sent");
  const network::RoomPoint from{house_.currentRoom(), pose->cell};
  const network::RoomPoint to = c.near ? network::RoomPoint{} : target(c, h, what);
  const network::HouseRoute r = network::planHouseRoute(h, from, to, plan::Algorithm::AStar, c.near ? c.name : "");
  if (!r.found) throw ConsoleError(what + ": " + r.error + "; nothing sent");
  checkRooms(r, h, what);
  // Keep the current room's live map, so the rooms to come are uploaded as the brick left them.
  house_.keepCurrentMap(h);
  active_ = true;
  switching_ = false;
  legs_ = r.legs;
  leg_ = 0;
  return routeText(r, h) + goals_.startPath(r.legs[0].cells, "leg 1 of " + std::to_string(r.legs.size()) + " in room " +
                                                                 std::to_string(house_.currentRoom()));
}

std::string RouteDriver::switchRoom() {
  const network::HouseLeg& next = legs_[leg_ + 1];
  const int from = house_.currentRoom(), to = next.room;
  const std::optional<Pose> pose = runner_.with([](link::Session& s) { return s.pose(); });
  const Dir heading = pose ? pose->heading : Dir::North;
  // The heading in the next room's frame through both rooms' places in the house.
  const auto& rooms = house_.house().rooms();
  const network::RoomTransform fromTo =
      rooms[static_cast<size_t>(to)].toHouse.inverse() * rooms[static_cast<size_t>(from)].toHouse;
  arrival_ = Pose{next.cells.front(), fromTo.apply(heading)};
  try {
    house_.switchTo(to);
  } catch (const ConsoleError& e) {
    active_ = false;
    goals_.giveUp(std::string("unreachable: ") + e.what());
    return std::string("route given up: ") + e.what() + "\n";
  }
  poseSeq_ = runner_.with([&](link::Session& s) { return s.setPose(arrival_); });
  goals_.clearBlocked();
  switching_ = true;
  since_ = std::chrono::steady_clock::now();
  ++leg_;
  return "at the gateway: room " + std::to_string(to) + " (" + rooms[static_cast<size_t>(to)].name +
         ") goes to the brick, the robot stands at " + cellText(arrival_.cell) + " there\n";
}

std::string RouteDriver::poll() {
  if (!active_) return "";
  if (switching_) return pollSwitch();
  if (goals_.active()) return "";
  if (goals_.outcome() != "reached") {
    active_ = false;
    return "route given up in room " + std::to_string(house_.currentRoom()) + "\n";
  }
  if (leg_ + 1 >= legs_.size()) {
    active_ = false;
    return "route done: the robot is at " + cellText(legs_.back().cells.back()) + " in room " +
           std::to_string(house_.currentRoom()) + "\n";
  }
  return switchRoom();
}

std::string RouteDriver::pollSwitch() {
  const bool ready = !house_.uploadPending() && runner_.with([&](link::Session& s) {
    return s.acknowledged(poseSeq_) && s.pose() && s.pose()->cell == arrival_.cell &&
           s.pose()->heading == arrival_.heading;
  });
  if (!ready) {
    if (secondsSince(since_) <= kSwitchGiveUpS) return "";
    active_ = false;
    goals_.giveUp("unreachable: the brick did not take the next room's map");
    return "route given up: the brick did not take room " + std::to_string(house_.currentRoom()) + "'s map within " +
           std::to_string(static_cast<int>(kSwitchGiveUpS)) + " s\n";
  }
  switching_ = false;
  const network::HouseLeg& leg = legs_[leg_];
  return "in room " + std::to_string(house_.currentRoom()) + ": " +
         goals_.startPath(leg.cells, "leg " + std::to_string(leg_ + 1) + " of " + std::to_string(legs_.size()));
}

}  // namespace nxtmap::console
