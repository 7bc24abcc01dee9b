#include "host/console/ConsoleHouse.hpp"

#include <algorithm>
#include <sstream>

#include "host/console/ConsoleCommand.hpp"
#include "host/console/MapView.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/network/HouseFiles.hpp"

namespace nxtmap::console {
namespace {

constexpr double kEchoWaitS = 10.0;  // an upload's echo: after this, a partial echo will do

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string cellText(Cell c) { return "(" + std::to_string(c.x) + "," + std::to_string(c.y) + ")"; }

Bounds boundsOf(const network::RoomMap& m) {
  return Bounds{static_cast<int16_t>(m.minX()), static_cast<int16_t>(m.minY()), static_cast<int16_t>(m.maxX()),
                static_cast<int16_t>(m.maxY())};
}

// `b` grown to hold the stored map `m` (when it has cells); `m`'s box when `b` is empty.
Bounds unionWith(Bounds b, const network::RoomMap& m) {
  if (m.width() <= 0 || m.height() <= 0) return b;
  if (b.empty()) return boundsOf(m);
  b.minX = static_cast<int16_t>(std::min<int>(b.minX, m.minX()));
  b.minY = static_cast<int16_t>(std::min<int>(b.minY, m.minY()));
  b.maxX = static_cast<int16_t>(std::max<int>(b.maxX, m.maxX()));
  b.maxY = static_cast<int16_t>(std::max<int>(b.maxY, m.maxY()));
  return b;
}

// Every cell of `m`, row by row from minY (what a MapChunk upload carries); `known` counts the known ones.
std::vector<CellState> roomCells(const network::RoomMap& m, size_t& known) {
  std::vector<CellState> cells;
  cells.reserve(static_cast<size_t>(m.width()) * static_cast<size_t>(m.height()));
  known = 0;
  for (int y = m.minY(); y <= m.maxY(); ++y) {
    for (int x = m.minX(); x <= m.maxX(); ++x) {
      const CellState st = m.at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)});
      known += st != CellState::Unknown ? 1 : 0;
      cells.push_back(st);
    }
  }
  return cells;
}

// Throws ConsoleError when room `node` has no map or one larger than the brick's grid.
void checkFitsBrick(const network::RoomNode& node, const link::Session& s) {
  const network::RoomMap& m = node.map;
  const int capW = s.hello() ? (1 << s.hello()->gridWidthLog2) : 64;
  const int capH = s.hello() ? (1 << s.hello()->gridHeightLog2) : 64;
  if (m.width() <= 0 || m.height() <= 0) throw ConsoleError(node.name + " has no map to send to the brick");
  if (m.width() > capW || m.height() > capH || m.width() > 128 || m.height() > 128) {
    throw ConsoleError(node.name + "'s map is " + std::to_string(m.width()) + " x " + std::to_string(m.height()) +
                       " cells, more than the brick holds (" + std::to_string(capW) + " x " + std::to_string(capH) +
                       ")");
  }
}

}  // namespace

ConsoleHouse::ConsoleHouse(link::LinkRunner& runner) : runner_(runner) {
  network::RoomNode first;
  first.name = "room0";
  house_.addRoom(std::move(first));
  placed_.push_back(true);
}

network::RoomMap ConsoleHouse::liveRoomMap(const link::Session& s) const {
  const Bounds b = unionWith(s.map().bounds(), house_.rooms()[static_cast<size_t>(current_)].map);
  if (b.empty()) return network::RoomMap();
  network::RoomMap m(b.minX, b.minY, b.width(), b.height());
  s.map().forEach([&](Cell c, CellState st) { m.set(c, st); });
  return m;
}

network::HouseNetwork ConsoleHouse::snapshot() const {
  network::HouseNetwork h = house_;
  if (!liveValid_) return h;
  runner_.with([&](link::Session& s) {
    if (s.map().known() > 0) h.rooms()[static_cast<size_t>(current_)].map = liveRoomMap(s);
    return 0;
  });
  return h;
}

void ConsoleHouse::useHouse(network::HouseNetwork house, double resolutionM, int room) {
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

void ConsoleHouse::uploadRoom(int room) {
  const network::RoomNode& node = house_.rooms()[static_cast<size_t>(room)];
  size_t known = 0;
  const std::vector<CellState> cells = roomCells(node.map, known);
  runner_.with([&](link::Session& s) {
    checkFitsBrick(node, s);
    echo_ = UploadEcho{true, s.map().hasEpoch(), s.map().epoch(), known, std::chrono::steady_clock::now()};
    s.uploadMap(boundsOf(node.map), cells, nextTransferId_++);
    return 0;
  });
  liveValid_ = false;
}

std::string ConsoleHouse::enterHouseRoom() {
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

void ConsoleHouse::keepCurrentMap(const network::HouseNetwork& snap) {
  house_.rooms()[static_cast<size_t>(current_)].map = snap.rooms()[static_cast<size_t>(current_)].map;
}

void ConsoleHouse::switchTo(int to) {
  keepCurrentMap(snapshot());
  uploadRoom(to);
  current_ = to;
}

std::string ConsoleHouse::pollUpload() {
  if (!echo_.pending) return "";
  const bool echoed = runner_.with([&](link::Session& s) {
    const bool newEpoch = s.map().hasEpoch() && (!echo_.hadEpoch || s.map().epoch() != echo_.epochBefore);
    if (!s.commandsDone() || !newEpoch) return false;
    return s.map().known() >= echo_.cells || (s.map().known() > 0 && secondsSince(echo_.since) > kEchoWaitS);
  });
  if (!echoed) return "";
  echo_.pending = false;
  liveValid_ = true;
  return "";
}

void ConsoleHouse::keepLeftRoom(const link::MirrorMap& left) {
  network::RoomMap& kept = house_.rooms()[static_cast<size_t>(current_)].map;
  const Bounds b = unionWith(left.bounds(), kept);
  network::RoomMap m(b.minX, b.minY, b.width(), b.height());
  left.forEach([&](Cell cell, CellState st) { m.set(cell, st); });
  kept = m;
}

std::string ConsoleHouse::pollRooms(const std::function<std::string()>& onNewRoom) {
  std::vector<link::RoomChange> changes = runner_.with([](link::Session& s) { return s.takeRoomChanges(); });
  std::string out;
  for (const link::RoomChange& c : changes) {
    if (liveValid_ && c.left.known() > 0) keepLeftRoom(c.left);  // as the brick last had it
    out += onNewRoom();
    out += startNewRoom(c);
  }
  return out;
}

std::string ConsoleHouse::startNewRoom(const link::RoomChange& c) {
  echo_.pending = false;
  liveValid_ = true;
  const int from = current_;
  network::RoomNode node;
  for (int k = static_cast<int>(house_.rooms().size());; ++k) {
    node.name = "room" + std::to_string(k);
    if (house_.roomIndex(node.name) < 0) break;
  }
  const bool placed = c.lastPose && placed_[static_cast<size_t>(from)];
  // The brick starts the new room's frame at the robot's pose: origin = its last cell in the old room,
  // +y along its heading there.
  if (placed) {
    node.toHouse = house_.rooms()[static_cast<size_t>(from)].toHouse *
                   network::RoomTransform::fromPose(c.lastPose->cell, c.lastPose->heading);
  }
  const bool gateway =
      placed && house_.rooms()[static_cast<size_t>(from)].map.at(c.lastPose->cell) != CellState::Occupied;
  current_ = house_.addRoom(std::move(node));
  placed_.push_back(placed);
  std::ostringstream o;
  o << "the brick went into a new room: room " << current_ << " (brick room " << c.toRoom << ")";
  if (!gateway) {
    o << ": not connected yet (where the robot left room " << from << " is not known)\n";
    return o.str();
  }
  house_.addGateway(network::Gateway{from, current_, {c.lastPose->cell}, {Cell{0, 0}}});
  o << ", joined to room " << from << " by a gateway at " << cellText(c.lastPose->cell) << "\n";
  return o.str();
}

std::string ConsoleHouse::roomLine(const network::HouseNetwork& h, size_t i, const std::optional<Pose>& pose) const {
  const network::RoomNode& r = h.rooms()[i];
  const bool current = static_cast<int>(i) == current_;
  std::ostringstream o;
  o << "room " << i << " " << r.name << (current ? " (current)" : "") << ": ";
  if (r.map.width() == 0)
    o << "no map yet";
  else
    o << r.map.width() << " x " << r.map.height() << " cells from "
      << cellText(Cell{static_cast<int16_t>(r.map.minX()), static_cast<int16_t>(r.map.minY())}) << ", "
      << r.map.count(CellState::Free) << " free, " << r.map.count(CellState::Occupied) << " occupied";
  if (current && pose) o << "; robot at " << cellText(pose->cell);
  if (!placed_[i]) o << "; not connected yet";
  const char* lead = "; exits: ";
  for (const network::Gateway& g : h.gateways()) {
    const bool a = g.roomA == static_cast<int>(i), b = g.roomB == static_cast<int>(i);
    if (!a && !b) continue;
    const std::vector<Cell>& here = a ? g.cellsA : g.cellsB;
    o << lead << "to room " << (a ? g.roomB : g.roomA) << " at " << cellText(here[here.size() / 2]);
    if (here.size() > 1) o << " (" << here.size() << " cells)";
    lead = ", ";
  }
  lead = "; labels: ";
  for (const auto& [name, cell] : r.labels) {
    o << lead << name << " " << cellText(cell);
    lead = ", ";
  }
  return o.str() + "\n";
}

std::string ConsoleHouse::roomsText() const {
  const network::HouseNetwork h = snapshot();
  const std::optional<Pose> pose = runner_.with([](link::Session& s) { return s.pose(); });
  std::string out;
  for (size_t i = 0; i < h.rooms().size(); ++i) out += roomLine(h, i, pose);
  return out;
}

std::string ConsoleHouse::saveHouse(const std::string& dir) const {
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

std::string ConsoleHouse::saveRoom(const std::string& file) {
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
