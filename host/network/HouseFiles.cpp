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

}  // namespace nxtmap::network
