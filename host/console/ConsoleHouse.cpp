// The console's house: rooms seen or loaded, room changes reported by the brick, routes across
// rooms driven leg by leg, and saving (see Console.hpp).
#include <sstream>

#include "host/console/Console.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/network/HouseFiles.hpp"

namespace nxtmap::console {
namespace {

constexpr double kEchoWaitS = 10.0;      // an upload's echo: after this, a partial echo will do
constexpr double kSwitchGiveUpS = 30.0;  // a room switch the brick does not confirm is given up

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string cellText(Cell c) { return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")"; }

}  // namespace

network::RoomMap Console::liveRoomMap(const link::Session& s) const {
  Bounds b = s.map().bounds();
  const network::RoomMap& stored = house_.rooms()[static_cast<size_t>(current_)].map;
  if (stored.width() > 0 && stored.height() > 0) {
    if (b.empty()) {
      b = Bounds{static_cast<int16_t>(stored.minX()), static_cast<int16_t>(stored.minY()),
                 static_cast<int16_t>(stored.maxX()), static_cast<int16_t>(stored.maxY())};
    } else {
      b.minX = static_cast<int16_t>(std::min<int>(b.minX, stored.minX()));
      b.minY = static_cast<int16_t>(std::min<int>(b.minY, stored.minY()));
      b.maxX = static_cast<int16_t>(std::max<int>(b.maxX, stored.maxX()));
      b.maxY = static_cast<int16_t>(std::max<int>(b.maxY, stored.maxY()));
    }
  }
  if (b.empty()) return network::RoomMap();
  network::RoomMap m(b.minX, b.minY, b.width(), b.height());
  s.map().forEach([&](Cell c, CellState st) { m.set(c, st); });
  return m;
}

network::HouseNetwork Console::snapshot() const {
  network::HouseNetwork h = house_;
  if (!liveValid_) return h;
  runner_.with([&](link::Session& s) {
    if (s.map().known() > 0) h.rooms()[static_cast<size_t>(current_)].map = liveRoomMap(s);
    return 0;
  });
  return h;
}

void Console::useHouse(network::HouseNetwork house, double resolutionM, int room) {
  const int n = static_cast<int>(house.rooms().size());
  if (room < 0 || room >= n) {
    throw ConsoleError("--room " + std::to_string(room) + ": the house has rooms 0.." + std::to_string(n - 1));
  }
  house_ = std::move(house);
  placed_.assign(house_.rooms().size(), true);
  resolutionM_ = resolutionM;
  current_ = room;
  liveValid_ = house_.rooms()[static_cast<size_t>(room)].map.width() == 0;
}

void Console::uploadRoom(int room) {
  const network::RoomNode& node = house_.rooms()[static_cast<size_t>(room)];
  const network::RoomMap& m = node.map;
  const Bounds window{static_cast<int16_t>(m.minX()), static_cast<int16_t>(m.minY()), static_cast<int16_t>(m.maxX()),
                      static_cast<int16_t>(m.maxY())};
  std::vector<CellState> cells;
  cells.reserve(static_cast<size_t>(m.width()) * static_cast<size_t>(m.height()));
  size_t known = 0;
  for (int y = m.minY(); y <= m.maxY(); ++y) {
    for (int x = m.minX(); x <= m.maxX(); ++x) {
      const CellState st = m.at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)});
      known += st != CellState::Unknown ? 1 : 0;
      cells.push_back(st);
    }
  }
  runner_.with([&](link::Session& s) {
    const int capW = s.hello() ? (1 << s.hello()->gridWidthLog2) : 64;
    const int capH = s.hello() ? (1 << s.hello()->gridHeightLog2) : 64;
    if (m.width() <= 0 || m.height() <= 0) throw ConsoleError(node.name + " has no map to send to the brick");
    if (m.width() > capW || m.height() > capH || m.width() > 128 || m.height() > 128) {
      throw ConsoleError(node.name + "'s map is " + std::to_string(m.width()) + " x " + std::to_string(m.height()) +
                         " cells, more than the brick holds (" + std::to_string(capW) + " x " + std::to_string(capH) +
                         ")");
    }
    echo_ = UploadEcho{};
    echo_.pending = true;
    echo_.hadEpoch = s.map().hasEpoch();
    echo_.epochBefore = s.map().epoch();
    echo_.cells = known;
    echo_.since = std::chrono::steady_clock::now();
    s.uploadMap(window, cells, nextTransferId_++);
    return 0;
  });
  liveValid_ = false;
}

std::string Console::enterHouseRoom() {
  const network::RoomNode& node = house_.rooms()[static_cast<size_t>(current_)];
  std::ostringstream o;
  o << "house: " << house_.rooms().size() << " rooms, " << house_.gateways().size()
    << " gateways; the brick is in room " << current_ << " (" << node.name << ")";
  if (node.map.width() == 0) {
    liveValid_ = true;
    o << ", which has no map yet\n";
    return o.str();
  }
  uploadRoom(current_);
  o << ": its map (" << node.map.width() << " x " << node.map.height() << " cells) goes to the brick\n";
  return o.str();
}

std::string Console::pollUpload() {
  if (!echo_.pending) return "";
  bool echoed = false;
  runner_.with([&](link::Session& s) {
    const bool newEpoch = s.map().hasEpoch() && (!echo_.hadEpoch || s.map().epoch() != echo_.epochBefore);
    if (!s.commandsDone() || !newEpoch) return 0;
    echoed = s.map().known() >= echo_.cells || (s.map().known() > 0 && secondsSince(echo_.since) > kEchoWaitS);
    return 0;
  });
  if (!echoed) return "";
  echo_.pending = false;
  liveValid_ = true;
  return "";
}

std::string Console::pollRooms() {
  std::vector<link::RoomChange> changes = runner_.with([](link::Session& s) { return s.takeRoomChanges(); });
  std::ostringstream o;
  for (link::RoomChange& c : changes) {
    // Keep the room it left, as the brick last had it.
    if (liveValid_ && c.left.known() > 0) {
      network::RoomMap& kept = house_.rooms()[static_cast<size_t>(current_)].map;
      Bounds b = c.left.bounds();
      if (kept.width() > 0) {
        b.minX = static_cast<int16_t>(std::min<int>(b.minX, kept.minX()));
        b.minY = static_cast<int16_t>(std::min<int>(b.minY, kept.minY()));
        b.maxX = static_cast<int16_t>(std::max<int>(b.maxX, kept.maxX()));
        b.maxY = static_cast<int16_t>(std::max<int>(b.maxY, kept.maxY()));
      }
      network::RoomMap m(b.minX, b.minY, b.width(), b.height());
      c.left.forEach([&](Cell cell, CellState st) { m.set(cell, st); });
      kept = m;
    }
    if (goal_.active || route_.active) {
      goal_.active = false;
      route_.active = false;
      goal_.outcome = "unreachable: the brick went into another room";
      o << "goal dropped: the brick went into another room\n";
    }
    echo_.pending = false;
    liveValid_ = true;
    blocked_.clear();
    const int from = current_;
    network::RoomNode node;
    for (int k = static_cast<int>(house_.rooms().size());; ++k) {
      node.name = "room" + std::to_string(k);
      if (house_.roomIndex(node.name) < 0) break;
    }
    bool placed = false, gateway = false;
    if (c.lastPose && placed_[static_cast<size_t>(from)]) {
      // The brick starts the new room's frame at the robot's pose: origin = its last cell in the
      // old room, +y along its heading there.
      node.toHouse = house_.rooms()[static_cast<size_t>(from)].toHouse *
                     network::RoomTransform::fromPose(c.lastPose->cell, c.lastPose->heading);
      placed = true;
      gateway = house_.rooms()[static_cast<size_t>(from)].map.at(c.lastPose->cell) != CellState::Occupied;
    }
    const int added = house_.addRoom(std::move(node));
    placed_.push_back(placed);
    o << "the brick went into a new room: room " << added << " (brick room " << c.toRoom << ")";
    if (gateway) {
      network::Gateway g;
      g.roomA = from;
      g.roomB = added;
      g.cellsA = {c.lastPose->cell};
      g.cellsB = {Cell{0, 0}};
      house_.addGateway(g);
      o << ", joined to room " << from << " by a gateway at " << cellText(c.lastPose->cell) << "\n";
    } else {
      o << ": not connected yet (where the robot left room " << from << " is not known)\n";
    }
    current_ = added;
  }
  return o.str();
}

std::string Console::roomsText() const {
  const network::HouseNetwork h = snapshot();
  const std::optional<Pose> pose = runner_.with([](link::Session& s) { return s.pose(); });
  std::ostringstream o;
  for (size_t i = 0; i < h.rooms().size(); ++i) {
    const network::RoomNode& r = h.rooms()[i];
    o << "room " << i << " " << r.name;
    if (static_cast<int>(i) == current_) o << " (current)";
    o << ": ";
    if (r.map.width() == 0)
      o << "no map yet";
    else
      o << r.map.width() << " x " << r.map.height() << " cells from "
        << cellText(Cell{static_cast<int16_t>(r.map.minX()), static_cast<int16_t>(r.map.minY())}) << ", "
        << r.map.count(CellState::Free) << " free, " << r.map.count(CellState::Occupied) << " occupied";
    if (static_cast<int>(i) == current_ && pose) o << "; robot at " << cellText(pose->cell);
    if (!placed_[i]) o << "; not connected yet";
    bool first = true;
    for (const network::Gateway& g : h.gateways()) {
      const bool a = g.roomA == static_cast<int>(i), b = g.roomB == static_cast<int>(i);
      if (!a && !b) continue;
      const std::vector<Cell>& here = a ? g.cellsA : g.cellsB;
      o << (first ? "; exits: " : ", ") << "to room " << (a ? g.roomB : g.roomA) << " at "
        << cellText(here[here.size() / 2]);
      if (here.size() > 1) o << " (" << here.size() << " cells)";
      first = false;
    }
    first = true;
    for (const auto& [name, cell] : r.labels) {
      o << (first ? "; labels: " : ", ") << name << " " << cellText(cell);
      first = false;
    }
    o << "\n";
  }
  return o.str();
}

std::string Console::startRoute(const ConsoleCommand& c) {
  const std::string what =
      c.near ? "route near " + c.name : "route " + c.name + " " + std::to_string(c.col) + " " + std::to_string(c.row);
  if (echo_.pending) waitFor([&] { return !echo_.pending; }, 5.0);
  if (!liveValid_) throw ConsoleError(what + ": the brick has not taken this room's map yet; nothing sent");
  const network::HouseNetwork h = snapshot();
  const std::optional<Pose> pose = runner_.with([](link::Session& s) { return s.pose(); });
  if (!pose) throw ConsoleError(what + ": the robot's position is not known yet; nothing sent");
  network::RoomPoint from{current_, pose->cell};
  network::RoomPoint to;
  const int n = static_cast<int>(h.rooms().size());
  if (!c.near) {
    int room = -1;
    if (!c.name.empty() && c.name.find_first_not_of("0123456789") == std::string::npos && c.name.size() <= 5) {
      room = std::stoi(c.name);
      if (room >= n) room = -1;
    } else {
      room = h.roomIndex(c.name);
    }
    if (room < 0) {
      throw ConsoleError(what + ": no room '" + c.name + "' (the house has rooms 0.." + std::to_string(n - 1) +
                         ", see rooms); nothing sent");
    }
    const network::RoomMap& m = h.rooms()[static_cast<size_t>(room)].map;
    if (c.col >= m.width() || c.row >= m.height()) {
      throw ConsoleError(what + ": outside room " + std::to_string(room) + "'s map (" + std::to_string(m.width()) +
                         " x " + std::to_string(m.height()) + " cells); nothing sent");
    }
    const Cell cell = network::mapCellToRoom(m, c.col, c.row);
    if (m.at(cell) == CellState::Occupied) throw ConsoleError(what + ": that cell is an obstacle; nothing sent");
    if (m.at(cell) == CellState::Unknown) throw ConsoleError(what + ": that cell is unexplored; nothing sent");
    to = network::RoomPoint{room, cell};
  }
  const network::HouseRoute r = network::planHouseRoute(h, from, to, plan::Algorithm::AStar, c.near ? c.name : "");
  if (!r.found) throw ConsoleError(what + ": " + r.error + "; nothing sent");
  for (size_t i = 1; i < r.rooms.size(); ++i) {
    const int room = r.rooms[i];
    if (!placed_[static_cast<size_t>(room)]) {
      throw ConsoleError(what + ": room " + std::to_string(room) + " is not connected to the house yet; nothing sent");
    }
    const network::RoomMap& m = h.rooms()[static_cast<size_t>(room)].map;
    const int cap = runner_.with([](link::Session& s) { return s.hello() ? (1 << s.hello()->gridWidthLog2) : 64; });
    if (m.width() > cap || m.height() > cap) {
      throw ConsoleError(what + ": room " + std::to_string(room) +
                         "'s map is larger than the brick holds; nothing sent");
    }
  }
  // Keep the current room's live map, so the rooms to come are uploaded as the brick left them.
  house_.rooms()[static_cast<size_t>(current_)].map = h.rooms()[static_cast<size_t>(current_)].map;
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
  route_ = RouteDrive{};
  route_.active = true;
  route_.legs = r.legs;
  route_.leg = 0;
  o << startPath(r.legs[0].cells, "leg 1 of " + std::to_string(r.legs.size()) + " in room " + std::to_string(current_));
  return o.str();
}

std::string Console::switchRoom() {
  const network::HouseLeg& next = route_.legs[route_.leg + 1];
  const int from = current_, to = next.room;
  // Keep the room the robot leaves, as the brick mapped it.
  const network::HouseNetwork h = snapshot();
  house_.rooms()[static_cast<size_t>(from)].map = h.rooms()[static_cast<size_t>(from)].map;
  const std::optional<Pose> pose = runner_.with([](link::Session& s) { return s.pose(); });
  const Dir heading = pose ? pose->heading : Dir::North;
  // The heading in the next room's frame through both rooms' places in the house.
  const network::RoomTransform fromTo =
      house_.rooms()[static_cast<size_t>(to)].toHouse.inverse() * house_.rooms()[static_cast<size_t>(from)].toHouse;
  route_.arrival = Pose{next.cells.front(), fromTo.apply(heading)};
  try {
    uploadRoom(to);
  } catch (const ConsoleError& e) {
    route_.active = false;
    goal_.outcome = std::string("unreachable: ") + e.what();
    return std::string("route given up: ") + e.what() + "\n";
  }
  route_.poseSeq = runner_.with([&](link::Session& s) { return s.setPose(route_.arrival); });
  current_ = to;
  blocked_.clear();
  route_.switching = true;
  route_.since = std::chrono::steady_clock::now();
  ++route_.leg;
  return "at the gateway: room " + std::to_string(to) + " (" + house_.rooms()[static_cast<size_t>(to)].name +
         ") goes to the brick, the robot stands at " + cellText(route_.arrival.cell) + " there\n";
}

std::string Console::pollRoute() {
  if (!route_.active) return "";
  if (!route_.switching) {
    if (goal_.active) return "";
    if (goal_.outcome != "reached") {
      route_.active = false;
      return "route given up in room " + std::to_string(current_) + "\n";
    }
    if (route_.leg + 1 >= route_.legs.size()) {
      route_.active = false;
      return "route done: the robot is at " + cellText(route_.legs.back().cells.back()) + " in room " +
             std::to_string(current_) + "\n";
    }
    return switchRoom();
  }
  const bool ready = !echo_.pending && runner_.with([&](link::Session& s) {
    return s.acknowledged(route_.poseSeq) && s.pose() && s.pose()->cell == route_.arrival.cell &&
           s.pose()->heading == route_.arrival.heading;
  });
  if (!ready) {
    if (secondsSince(route_.since) <= kSwitchGiveUpS) return "";
    route_.active = false;
    goal_.outcome = "unreachable: the brick did not take the next room's map";
    return "route given up: the brick did not take room " + std::to_string(current_) + "'s map within " +
           std::to_string(static_cast<int>(kSwitchGiveUpS)) + " s\n";
  }
  route_.switching = false;
  const network::HouseLeg& leg = route_.legs[route_.leg];
  return "in room " + std::to_string(current_) + ": " +
         startPath(leg.cells, "leg " + std::to_string(route_.leg + 1) + " of " + std::to_string(route_.legs.size()));
}

std::string Console::saveHouse(const std::string& dir) {
  if (echo_.pending) waitFor([&] { return !echo_.pending; }, 5.0);
  network::HouseNetwork h = snapshot();
  std::string notes;
  for (size_t i = 0; i < h.rooms().size(); ++i) {
    if (h.rooms()[i].map.width() == 0) h.rooms()[i].map = network::RoomMap(0, 0, 1, 1);  // nothing known yet
    if (!placed_[i]) {
      notes += "note: room " + std::to_string(i) +
               " is not connected: its place in the house is unknown (written at the house origin)\n";
    }
  }
  std::string error;
  if (!network::saveHouse(h, resolutionM_, dir, error)) throw ConsoleError("save: " + error);
  return notes + "saved house " + dir + ": " + std::to_string(h.rooms().size()) + " rooms, " +
         std::to_string(h.gateways().size()) + " gateways\n";
}

std::string Console::saveRoom(const std::string& file) {
  MapView v = runner_.with([&](link::Session& s) { return viewOf(s, {}); });
  if (v.bounds.empty()) throw ConsoleError("save: there is no map yet");
  for (const auto& [name, cell] : labels()) {
    int col = 0, row = 0;
    if (v.toMap(cell, col, row)) v.map.setLabel(name, mapio::CellBlock{col, row, 1, 1});
  }
  std::string error;
  if (!mapio::saveRosMap(v.map, file, error)) throw ConsoleError("save: " + error);
  return "saved " + file + " and " + mapio::pgmNameFor(file) + " (" + std::to_string(v.map.width()) + " x " +
         std::to_string(v.map.height()) + " cells)\n";
}

}  // namespace nxtmap::console
