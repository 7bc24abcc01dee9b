// loadHouse (declared in HouseFiles.hpp): reads and checks a house directory. house.yaml is read only
// when it is a regular file of at most kMaxHouseFileBytes; every number from it and from the room
// maps is checked against HouseLimits before any arithmetic on it, and the whole network is checked
// (HouseNetwork::validate) before it is returned. The first problem gives one message naming the
// file, the room or gateway and the field.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "host/mapio/MapFiles.hpp"
#include "host/network/HouseFiles.hpp"
#include "host/network/HouseLimits.hpp"
#include "host/sim/InputFile.hpp"

namespace nxtmap::network {
namespace fs = std::filesystem;
namespace {

constexpr double kMinResolutionM = 0.001, kMaxResolutionM = 10.0;

CellState fromOcc(mapio::Occupancy o) {
  return o == mapio::Occupancy::Free ? CellState::Free
                                     : (o == mapio::Occupancy::Occupied ? CellState::Occupied : CellState::Unknown);
}

// What the file holds instead of a good value, for a message: ", not '1e300'" (cut short), ", not a list or
// mapping", " (it is missing)".
std::string shown(const YAML::Node& n) {
  if (!n) return " (it is missing)";
  if (!n.IsScalar()) return ", not a list or mapping";
  const std::string s = n.Scalar();
  return ", not '" + (s.size() > 24 ? s.substr(0, 24) + "..." : s) + "'";
}

std::string number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

const std::string kCoordinateRange = std::to_string(-kMaxCoordCells) + ".." + std::to_string(kMaxCoordCells);

// Reads one house directory; each read* step returns false with error_ set at the first problem.
class HouseReader {
 public:
  explicit HouseReader(const std::string& dir) : dir_(dir), where_((fs::path(dir) / kHouseFileName).string()) {}
  HouseLoad read();

 private:
  bool fail(const std::string& what) {
    error_ = where_ + ": " + what;
    return false;
  }
  bool readHouse(const YAML::Node& y, HouseNetwork& net);
  bool readResolution(const YAML::Node& n);
  bool readRoom(const YAML::Node& r, HouseNetwork& net);
  bool readRoomMap(const YAML::Node& r, RoomNode& node);
  bool placeRoomMap(const mapio::OccupancyMap& m, RoomNode& node);
  bool readPose(const YAML::Node& r, RoomNode& node);
  bool readLabels(const YAML::Node& r, RoomNode& node);
  bool readGateway(const YAML::Node& g, size_t index, HouseNetwork& net);
  bool readCells(const YAML::Node& n, const std::string& field, std::vector<Cell>& out);
  bool readCell(const YAML::Node& n, const std::string& field, Cell& out);
  bool readWhole(const YAML::Node& n, int lo, int hi, const std::string& field, int& out);

  std::string dir_, where_, error_;
  double res_ = 0.10;  // metres per cell
  long cells_ = 0;     // room map cells read so far
};

HouseLoad HouseReader::read() {
  HouseLoad out;
  std::error_code ec;
  if (!fs::exists(where_, ec)) {
    out.error = where_ + ": no house file (is " + dir_ + " a house directory?)";
    return out;
  }
  const std::optional<std::string> text = sim::readInputFile(where_, kMaxHouseFileBytes, "house file", out.error);
  if (!text) return out;
  HouseNetwork net;
  try {
    if (!readHouse(YAML::Load(*text), net)) {
      out.error = error_;
      return out;
    }
  } catch (const YAML::Exception& e) {
    out.error = where_ + ": broken YAML (" + e.what() + ")";
    return out;
  }
  std::string e;
  if (!net.validate(e)) {
    out.error = where_ + ": " + e;
    return out;
  }
  out.network = std::move(net);
  out.resolutionM = res_;
  return out;
}

bool HouseReader::readHouse(const YAML::Node& y, HouseNetwork& net) {
  if (!y.IsMap() || !y["format"] || y["format"].as<std::string>() != "nxtmap-house-1") {
    return fail("not an nxtmap house file (format: nxtmap-house-1 expected)");
  }
  if (!readResolution(y["resolution"])) return false;
  const YAML::Node rooms = y["rooms"];
  if (!rooms || !rooms.IsSequence() || rooms.size() == 0) return fail("'rooms' must be a non-empty list");
  if (rooms.size() > static_cast<size_t>(kMaxRooms)) {
    return fail("'rooms' lists " + std::to_string(rooms.size()) + " rooms, more than " + std::to_string(kMaxRooms));
  }
  for (const YAML::Node& r : rooms) {
    if (!readRoom(r, net)) return false;
  }
  const YAML::Node gws = y["gateways"];
  if (!gws) return true;
  if (!gws.IsSequence()) return fail("'gateways' must be a list");
  for (size_t i = 0; i < gws.size(); ++i) {
    if (!readGateway(gws[i], i, net)) return false;
  }
  return true;
}

bool HouseReader::readResolution(const YAML::Node& n) {
  double res = 0.0;
  try {
    res = n && n.IsScalar() ? n.as<double>() : 0.0;
  } catch (const YAML::BadConversion&) {
    res = 0.0;
  }
  if (!(res >= kMinResolutionM && res <= kMaxResolutionM)) {
    return fail("resolution must be a number of metres in " + number(kMinResolutionM) + ".." + number(kMaxResolutionM) +
                shown(n));
  }
  res_ = res;
  return true;
}

bool HouseReader::readRoom(const YAML::Node& r, HouseNetwork& net) {
  RoomNode node;
  node.name = r["name"] ? r["name"].as<std::string>() : "";
  if (!validRoomName(node.name)) {
    return fail("room name '" + node.name + "' is not 1-64 of A-Z a-z 0-9 _ - starting with a letter");
  }
  if (net.roomIndex(node.name) >= 0) return fail("two rooms are named '" + node.name + "'");
  if (!readRoomMap(r, node) || !readPose(r, node) || !readLabels(r, node)) return false;
  net.addRoom(std::move(node));
  return true;
}

bool HouseReader::readRoomMap(const YAML::Node& r, RoomNode& node) {
  const std::string which = "room '" + node.name + "'";
  const std::string mapFile = r["map"] ? r["map"].as<std::string>() : "";
  if (mapFile.empty() || mapFile.find('/') != std::string::npos) {
    return fail(which + " needs 'map', a file name in the house directory");
  }
  const fs::path path = fs::path(dir_) / mapFile;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) return fail(which + ": map " + mapFile + " is not a regular file");
  const mapio::MapLoad ml = mapio::loadRosMap(path.string());
  if (!ml.map) return fail(which + ": " + ml.error);
  return placeRoomMap(*ml.map, node);
}

// The ROS map's cells into the room's frame; its origin must be whole cells within the coordinate range.
bool HouseReader::placeRoomMap(const mapio::OccupancyMap& m, RoomNode& node) {
  const std::string which = "room '" + node.name + "'";
  const double ox = m.origin().x / res_, oy = m.origin().y / res_;
  const double limit = kMaxCoordCells;
  if (!(std::fabs(ox) <= limit && std::fabs(oy) <= limit)) {
    return fail(which + ": its map's origin [" + number(m.origin().x) + ", " + number(m.origin().y) +
                "] m lies beyond cells " + kCoordinateRange + " of the room's frame (" + number(limit * res_) + " m)");
  }
  if (std::fabs(m.resolutionM() - res_) > 1e-9 || std::fabs(ox - std::round(ox)) > 1e-6 ||
      std::fabs(oy - std::round(oy)) > 1e-6 || m.origin().yaw != 0.0) {
    return fail(which + ": its map's resolution or origin is not on the house's cell grid");
  }
  const int minX = static_cast<int>(std::lround(ox)), minY = static_cast<int>(std::lround(oy));
  if (minX + m.width() - 1 > kMaxCoordCells || minY + m.height() - 1 > kMaxCoordCells) {
    return fail(which + ": its map (" + std::to_string(m.width()) + " x " + std::to_string(m.height()) +
                " cells from cell " + std::to_string(minX) + ", " + std::to_string(minY) + ") reaches beyond cells " +
                kCoordinateRange + " of the room's frame");
  }
  cells_ += static_cast<long>(m.width()) * m.height();
  if (cells_ > kMaxRoomCells) {
    return fail(which + ": the room maps hold more than " + std::to_string(kMaxRoomCells) + " cells together");
  }
  node.map = RoomMap(minX, minY, m.width(), m.height());
  for (int row = 0; row < m.height(); ++row) {
    for (int col = 0; col < m.width(); ++col) node.map.set(mapCellToRoom(node.map, col, row), fromOcc(m.at(col, row)));
  }
  return true;
}

bool HouseReader::readPose(const YAML::Node& r, RoomNode& node) {
  const std::string which = "room '" + node.name + "'";
  const YAML::Node t = r["to_house"];
  if (!t || !t.IsMap() || !t["x"] || !t["y"] || !t["quarter_turns_clockwise"]) {
    return fail(which + " needs to_house {x, y, quarter_turns_clockwise}");
  }
  int x = 0, y = 0, q = 0;
  if (!readWhole(t["quarter_turns_clockwise"], 0, 3, which + ": quarter_turns_clockwise", q) ||
      !readWhole(t["x"], -kMaxCoordCells, kMaxCoordCells, which + ": to_house x", x) ||
      !readWhole(t["y"], -kMaxCoordCells, kMaxCoordCells, which + ": to_house y", y)) {
    return false;
  }
  node.toHouse = RoomTransform::fromParts(x, y, q);
  return true;
}

bool HouseReader::readLabels(const YAML::Node& r, RoomNode& node) {
  const std::string which = "room '" + node.name + "'";
  const YAML::Node labels = r["labels"];
  if (!labels) return true;
  if (!labels.IsMap()) return fail(which + ": labels must be a mapping NAME: [x, y]");
  for (const auto& kv : labels) {
    const std::string name = kv.first.as<std::string>();
    if (!mapio::OccupancyMap::validLabelName(name) || !kv.second.IsSequence() || kv.second.size() != 2) {
      return fail(which + ": label '" + name + "' must be NAME: [x, y]");
    }
    if (!readCell(kv.second, which + ": label '" + name + "'", node.labels[name])) return false;
  }
  return true;
}

bool HouseReader::readGateway(const YAML::Node& g, size_t index, HouseNetwork& net) {
  const std::string which = "gateway " + std::to_string(index);
  if (!g.IsMap() || !g["rooms"] || !g["rooms"].IsSequence() || g["rooms"].size() != 2) {
    return fail(which + " needs rooms: [A, B]");
  }
  Gateway gw;
  gw.roomA = net.roomIndex(g["rooms"][0].as<std::string>());
  gw.roomB = net.roomIndex(g["rooms"][1].as<std::string>());
  if (gw.roomA < 0 || gw.roomB < 0) return fail(which + " names a room that is not in the house");
  if (!readCells(g["cells_a"], which + ": cells_a", gw.cellsA) ||
      !readCells(g["cells_b"], which + ": cells_b", gw.cellsB)) {
    return false;
  }
  net.addGateway(std::move(gw));
  return true;
}

// A list of [x, y] cells.
bool HouseReader::readCells(const YAML::Node& n, const std::string& field, std::vector<Cell>& out) {
  if (!n || !n.IsSequence()) return fail(field + " must be a list of [x, y]");
  for (size_t i = 0; i < n.size(); ++i) {
    Cell c;
    if (!n[i].IsSequence() || n[i].size() != 2) return fail(field + " must be a list of [x, y]");
    if (!readCell(n[i], field + " [" + std::to_string(i) + "]", c)) return false;
    out.push_back(c);
  }
  return true;
}

// An [x, y] pair of whole numbers within the coordinate range.
bool HouseReader::readCell(const YAML::Node& n, const std::string& field, Cell& out) {
  int x = 0, y = 0;
  if (!readWhole(n[0], -kMaxCoordCells, kMaxCoordCells, field + " x", x) ||
      !readWhole(n[1], -kMaxCoordCells, kMaxCoordCells, field + " y", y)) {
    return false;
  }
  out = Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)};
  return true;
}

bool HouseReader::readWhole(const YAML::Node& n, int lo, int hi, const std::string& field, int& out) {
  long long v = 0;
  bool ok = n && n.IsScalar();
  try {
    if (ok) v = n.as<long long>();
  } catch (const YAML::BadConversion&) {
    ok = false;
  }
  if (!ok || v < lo || v > hi) {
    return fail(field + " must be a whole number in " + std::to_string(lo) + ".." + std::to_string(hi) + shown(n));
  }
  out = static_cast<int>(v);
  return true;
}

}  // namespace

HouseLoad loadHouse(const std::string& dir) { return HouseReader(dir).read(); }

}  // namespace nxtmap::network
