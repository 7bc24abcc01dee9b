// HouseFiles: a house on disk is a directory holding
//   house.yaml      the network: rooms (name, map file, pose in the house frame, labels) and gateways
//   <room>.yaml/pgm one ROS map_server map per room, in the room's own frame (host/mapio writes them;
//                   they load unchanged in RViz / Nav2: trinary, 0 occupied, 254 free, 205 unknown)
// Cells in house.yaml are room-frame cells (x right, y up, the room's entrance at 0,0); a room map's
// lower-left pixel is cell (origin_x / resolution, origin_y / resolution) of its room.
//
// Saving is atomic for the whole house (fileio::StagingDirectory): everything is written into a fresh
// sibling directory DIR.saving-<pid>, every file flushed to the disk, which then replaces the target in
// one rename (an exchange when the target exists), so a crash leaves either the old house or the new
// one, never a mixture; the next save removes staging directories of killed saves. An existing target
// must be a house directory (holding house.yaml) or empty; the folder it is in must exist (nothing else
// is created); "DIR/" names DIR. Loading checks everything before it returns a network:
// a missing room map, a bad gateway or broken YAML gives one message and no network.
#pragma once

#include <optional>
#include <string>

#include "host/mapio/OccupancyMap.hpp"
#include "host/network/HouseNetwork.hpp"

namespace nxtmap::network {

constexpr const char* kHouseFileName = "house.yaml";

struct HouseLoad {
  std::optional<HouseNetwork> network;
  double resolutionM = 0.10;
  std::string error;  // names the file and the problem when network is empty
};

// Room names: 1..64 of [A-Za-z0-9_-], starting with a letter (they name files).
bool validRoomName(const std::string& name);

bool saveHouse(const HouseNetwork& house, double resolutionM, const std::string& dir, std::string& error);
// The checks saveHouse makes of `dir` before it writes anything (for a caller to refuse early): an existing
// target is a house directory or empty, the folder it goes in exists. False with `error` set.
bool checkHouseTarget(const std::string& dir, std::string& error);
// Reads and checks a house directory (HouseReader.cpp): house.yaml only when it is a regular file of at
// most kMaxHouseFileBytes; every number in it and in the room maps within HouseLimits (resolution
// 0.001..10 m, cells and to_house within -8192..8192, the house at most 2048 cells a side, ...).
HouseLoad loadHouse(const std::string& dir);

// A room map as a ROS-style map (col right, row down; origin = the lower-left cell in metres).
mapio::OccupancyMap toOccupancyMap(const RoomMap& room, double resolutionM);
// The house frame's merged map the same way.
mapio::OccupancyMap mergedOccupancyMap(const HouseNetwork& house, double resolutionM);
// Map cell (col, row) of a room-frame cell, and back.
inline void roomCellToMap(const RoomMap& m, Cell c, int& col, int& row) {
  col = c.x - m.minX();
  row = m.maxY() - c.y;
}
inline Cell mapCellToRoom(const RoomMap& m, int col, int row) {
  return Cell{static_cast<int16_t>(col + m.minX()), static_cast<int16_t>(m.maxY() - row)};
}

}  // namespace nxtmap::network
