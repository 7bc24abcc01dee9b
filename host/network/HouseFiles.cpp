#include "host/network/HouseFiles.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "host/fileio/AtomicFile.hpp"
#include "host/fileio/StagingDirectory.hpp"
#include "host/mapio/MapFiles.hpp"

namespace nxtmap::network {
namespace fs = std::filesystem;
namespace {

mapio::Occupancy toOcc(CellState s) {
  return s == CellState::Free ? mapio::Occupancy::Free
                              : (s == CellState::Occupied ? mapio::Occupancy::Occupied : mapio::Occupancy::Unknown);
}
CellState fromOcc(mapio::Occupancy o) {
  return o == mapio::Occupancy::Free ? CellState::Free
                                     : (o == mapio::Occupancy::Occupied ? CellState::Occupied : CellState::Unknown);
}

std::string cellList(const std::vector<Cell>& cells) {
  std::ostringstream o;
  o << "[";
  for (size_t i = 0; i < cells.size(); ++i) o << (i ? ", " : "") << "[" << cells[i].x << ", " << cells[i].y << "]";
  o << "]";
  return o.str();
}

std::string houseYaml(const HouseNetwork& h, double res) {
  std::ostringstream o;
  o << "# nxtmap house: one ROS map_server map per room (each in its own frame), the rooms' poses in the\n"
    << "# house frame (room 0's frame) and the gateways between rooms. Cells are room-frame cells: x right,\n"
    << "# y up, the room's entrance at 0,0; a room map's lower-left pixel is cell origin / resolution.\n"
    << "format: nxtmap-house-1\n"
    << "resolution: " << res << "\n"
    << "rooms:\n";
  for (const RoomNode& r : h.rooms()) {
    o << "  - name: " << r.name << "\n"
      << "    map: " << r.name << ".yaml\n"
      << "    to_house: {x: " << r.toHouse.x() << ", y: " << r.toHouse.y()
      << ", quarter_turns_clockwise: " << r.toHouse.quarterTurns() << "}\n";
    if (r.labels.empty()) {
      o << "    labels: {}\n";
    } else {
      o << "    labels:\n";
      for (const auto& [name, c] : r.labels) o << "      " << name << ": [" << c.x << ", " << c.y << "]\n";
    }
  }
  o << "gateways:" << (h.gateways().empty() ? " []\n" : "\n");
  for (const Gateway& g : h.gateways()) {
    o << "  - rooms: [" << h.rooms()[static_cast<size_t>(g.roomA)].name << ", "
      << h.rooms()[static_cast<size_t>(g.roomB)].name << "]\n"
      << "    cells_a: " << cellList(g.cellsA) << "\n"
      << "    cells_b: " << cellList(g.cellsB) << "\n";
  }
  return o.str();
}

// Reads [x, y] pairs.
bool readCells(const YAML::Node& n, std::vector<Cell>& out) {
  if (!n || !n.IsSequence()) return false;
  for (const YAML::Node& c : n) {
    if (!c.IsSequence() || c.size() != 2) return false;
    const int x = c[0].as<int>(), y = c[1].as<int>();
    if (x < INT16_MIN || x > INT16_MAX || y < INT16_MIN || y > INT16_MAX) return false;
    out.push_back(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)});
  }
  return true;
}

}  // namespace

bool validRoomName(const std::string& name) {
  if (name.empty() || name.size() > 64 || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (const char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  }
  return true;
}

mapio::OccupancyMap toOccupancyMap(const RoomMap& room, double res) {
  mapio::OccupancyMap m(std::max(room.width(), 1), std::max(room.height(), 1), mapio::Occupancy::Unknown, res,
                        mapio::MapOrigin{room.minX() * res, room.minY() * res, 0.0});
  for (int row = 0; row < room.height(); ++row) {
    for (int col = 0; col < room.width(); ++col) m.set(col, row, toOcc(room.at(mapCellToRoom(room, col, row))));
  }
  return m;
}

mapio::OccupancyMap mergedOccupancyMap(const HouseNetwork& house, double res) {
  return toOccupancyMap(house.merged(), res);
}

bool checkHouseTarget(const std::string& dir, std::string& error) {
  const fs::path target = fileio::directoryTarget(dir);
  std::error_code ec;
  if (fs::exists(target, ec)) {
    if (!fs::is_directory(target, ec)) {
      error = dir + ": exists and is not a directory";
      return false;
    }
    if (!fs::exists(target / kHouseFileName, ec) && !fs::is_empty(target, ec)) {
      error = dir + ": is neither empty nor a house directory (no " + kHouseFileName + "): not overwritten";
      return false;
    }
  }
  return fileio::checkDirectoryTarget(dir, error);
}

bool saveHouse(const HouseNetwork& house, double res, const std::string& dir, std::string& error) {
  if (!house.validate(error)) {
    error = "cannot save the house: " + error;
    return false;
  }
  for (const RoomNode& r : house.rooms()) {
    if (!validRoomName(r.name)) {
      error = "cannot save the house: room name '" + r.name + "' is not 1-64 of A-Z a-z 0-9 _ - starting with a letter";
      return false;
    }
  }
  if (!checkHouseTarget(dir, error)) return false;
  // Every file goes into a staging sibling (each flushed to the disk), which then replaces the target whole.
  fileio::StagingDirectory stage;
  if (!stage.open(dir, error)) return false;
  for (const RoomNode& r : house.rooms()) {
    if (!mapio::saveRosMap(toOccupancyMap(r.map, res), (stage.path() / (r.name + ".yaml")).string(), error)) {
      return false;
    }
  }
  if (!fileio::writeFileAtomically((stage.path() / kHouseFileName).string(), houseYaml(house, res), error)) {
    return false;
  }
  return stage.commit(error);
}

HouseLoad loadHouse(const std::string& dir) {
  HouseLoad out;
  const fs::path file = fs::path(dir) / kHouseFileName;
  const std::string where = file.string();
  std::error_code ec;
  if (!fs::exists(file, ec)) {
    out.error = where + ": no house file (is " + dir + " a house directory?)";
    return out;
  }
  HouseNetwork net;
  try {
    const YAML::Node y = YAML::LoadFile(file.string());
    if (!y.IsMap() || !y["format"] || y["format"].as<std::string>() != "nxtmap-house-1") {
      out.error = where + ": not an nxtmap house file (format: nxtmap-house-1 expected)";
      return out;
    }
    const double res = y["resolution"] ? y["resolution"].as<double>() : 0.0;
    if (!(res > 0.0 && res <= 10.0)) {
      out.error = where + ": resolution must be a number of metres above 0";
      return out;
    }
    out.resolutionM = res;
    const YAML::Node rooms = y["rooms"];
    if (!rooms || !rooms.IsSequence() || rooms.size() == 0) {
      out.error = where + ": 'rooms' must be a non-empty list";
      return out;
    }
    for (const YAML::Node& r : rooms) {
      RoomNode node;
      node.name = r["name"] ? r["name"].as<std::string>() : "";
      if (!validRoomName(node.name)) {
        out.error = where + ": room name '" + node.name + "' is not 1-64 of A-Z a-z 0-9 _ - starting with a letter";
        return out;
      }
      if (net.roomIndex(node.name) >= 0) {
        out.error = where + ": two rooms are named '" + node.name + "'";
        return out;
      }
      const std::string mapFile = r["map"] ? r["map"].as<std::string>() : "";
      if (mapFile.empty() || mapFile.find('/') != std::string::npos) {
        out.error = where + ": room '" + node.name + "' needs 'map', a file name in the house directory";
        return out;
      }
      const mapio::MapLoad ml = mapio::loadRosMap((fs::path(dir) / mapFile).string());
      if (!ml.map) {
        out.error = where + ": room '" + node.name + "': " + ml.error;
        return out;
      }
      const mapio::OccupancyMap& m = *ml.map;
      const double ox = m.origin().x / res, oy = m.origin().y / res;
      if (std::fabs(m.resolutionM() - res) > 1e-9 || std::fabs(ox - std::round(ox)) > 1e-6 ||
          std::fabs(oy - std::round(oy)) > 1e-6 || m.origin().yaw != 0.0) {
        out.error = where + ": room '" + node.name + "': its map's resolution or origin is not on the house's cell grid";
        return out;
      }
      node.map = RoomMap(static_cast<int>(std::lround(ox)), static_cast<int>(std::lround(oy)), m.width(), m.height());
      for (int row = 0; row < m.height(); ++row) {
        for (int col = 0; col < m.width(); ++col) node.map.set(mapCellToRoom(node.map, col, row), fromOcc(m.at(col, row)));
      }
      const YAML::Node t = r["to_house"];
      if (!t || !t.IsMap() || !t["x"] || !t["y"] || !t["quarter_turns_clockwise"]) {
        out.error = where + ": room '" + node.name + "' needs to_house {x, y, quarter_turns_clockwise}";
        return out;
      }
      const int q = t["quarter_turns_clockwise"].as<int>();
      if (q < 0 || q > 3) {
        out.error = where + ": room '" + node.name + "': quarter_turns_clockwise must be 0..3";
        return out;
      }
      node.toHouse = RoomTransform::fromParts(t["x"].as<int>(), t["y"].as<int>(), q);
      if (const YAML::Node labels = r["labels"]) {
        if (!labels.IsMap()) {
          out.error = where + ": room '" + node.name + "': labels must be a mapping NAME: [x, y]";
          return out;
        }
        for (const auto& kv : labels) {
          const std::string name = kv.first.as<std::string>();
          const YAML::Node v = kv.second;
          if (!mapio::OccupancyMap::validLabelName(name) || !v.IsSequence() || v.size() != 2) {
            out.error = where + ": room '" + node.name + "': label '" + name + "' must be NAME: [x, y]";
            return out;
          }
          node.labels[name] = Cell{static_cast<int16_t>(v[0].as<int>()), static_cast<int16_t>(v[1].as<int>())};
        }
      }
      net.addRoom(std::move(node));
    }
    if (const YAML::Node gws = y["gateways"]) {
      if (!gws.IsSequence()) {
        out.error = where + ": 'gateways' must be a list";
        return out;
      }
      for (size_t i = 0; i < gws.size(); ++i) {
        const YAML::Node g = gws[i];
        const std::string which = where + ": gateway " + std::to_string(i);
        if (!g.IsMap() || !g["rooms"] || !g["rooms"].IsSequence() || g["rooms"].size() != 2) {
          out.error = which + " needs rooms: [A, B]";
          return out;
        }
        Gateway gw;
        gw.roomA = net.roomIndex(g["rooms"][0].as<std::string>());
        gw.roomB = net.roomIndex(g["rooms"][1].as<std::string>());
        if (gw.roomA < 0 || gw.roomB < 0) {
          out.error = which + " names a room that is not in the house";
          return out;
        }
        if (!readCells(g["cells_a"], gw.cellsA) || !readCells(g["cells_b"], gw.cellsB)) {
          out.error = which + ": cells_a and cells_b must be lists of [x, y]";
          return out;
        }
        net.addGateway(std::move(gw));
      }
    }
  } catch (const YAML::Exception& e) {
    out.error = where + ": broken YAML (" + e.what() + ")";
    return out;
  }
  std::string e;
  if (!net.validate(e)) {
    out.error = where + ": " + e;
    return out;
  }
  out.network = std::move(net);
  return out;
}

}  // namespace nxtmap::network
