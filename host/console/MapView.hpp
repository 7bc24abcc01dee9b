// MapView: the PC's map of the current room as an OccupancyMap over the known cells' bounding box
// (and the robot's cell), with the robot; what the console plans on, prints and exports.
#pragma once
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "host/link/Session.hpp"
#include "host/mapio/OccupancyMap.hpp"
#include "host/plan/Traversability.hpp"
#include "host/report/MapText.hpp"

namespace nxtmap::console {

// column = x - minX, row = maxY - y (row grows down, +y is the robot's initial forward).
struct MapView {
  mapio::OccupancyMap map;
  Bounds bounds;
  std::optional<plan::MapCell> robot;  // when the pose is known and inside
  Dir heading = Dir::North;
  bool toMap(Cell c, int& col, int& row) const;
  Cell toCell(int col, int row) const;
  CellState stateAt(int col, int row) const;  // inside the map
  std::optional<report::RobotMark> robotMark() const;
};

// The session's map with the cells the brick reported blocked (room-frame x, y) as obstacles.
MapView viewOf(const link::Session& session, const std::set<std::pair<int, int>>& blocked = {});

// The console's map display ("(no map yet)" for an empty view).
std::string mapText(const MapView& v);

// `export FILE.png`: the view's picture (report::GridImage, 8 px a cell); false with `error` set when
// the file cannot be written.
bool writeMapPicture(const MapView& v, const std::string& path, std::string& error);

}  // namespace nxtmap::console
