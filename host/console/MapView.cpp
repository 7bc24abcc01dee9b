#include "host/console/MapView.hpp"

#include <algorithm>

#include "host/report/GridImage.hpp"

namespace nxtmap::console {

bool MapView::toMap(Cell c, int& col, int& row) const {
  col = c.x - bounds.minX;
  row = bounds.maxY - c.y;
  return map.inside(col, row);
}

Cell MapView::toCell(int col, int row) const {
  return Cell{static_cast<int16_t>(bounds.minX + col), static_cast<int16_t>(bounds.maxY - row)};
}

CellState MapView::stateAt(int col, int row) const {
  switch (map.at(col, row)) {
    case mapio::Occupancy::Free: return CellState::Free;
    case mapio::Occupancy::Occupied: return CellState::Occupied;
    default: return CellState::Unknown;
  }
}

std::optional<report::RobotMark> MapView::robotMark() const {
  if (!robot) return std::nullopt;
  static const sim::Heading kHeading[4] = {sim::Heading::N, sim::Heading::E, sim::Heading::S, sim::Heading::W};
  return report::RobotMark{robot->col, robot->row, kHeading[static_cast<int>(heading)]};
}

namespace {

// The known cells' box grown to hold the robot's cell.
Bounds viewBounds(const link::Session& s) {
  Bounds b = s.map().bounds();
  if (!s.pose()) return b;
  const Cell r = s.pose()->cell;
  if (b.empty()) b = Bounds{r.x, r.y, r.x, r.y};
  b.minX = std::min(b.minX, r.x);
  b.maxX = std::max(b.maxX, r.x);
  b.minY = std::min(b.minY, r.y);
  b.maxY = std::max(b.maxY, r.y);
  return b;
}

void markOccupied(MapView& v, Cell c) {
  int col = 0, row = 0;
  if (v.toMap(c, col, row)) v.map.set(col, row, mapio::Occupancy::Occupied);
}

}  // namespace

MapView viewOf(const link::Session& s, const std::set<std::pair<int, int>>& blocked) {
  MapView v;
  v.bounds = viewBounds(s);
  if (v.bounds.empty()) return v;
  v.map = mapio::OccupancyMap(v.bounds.width(), v.bounds.height(), mapio::Occupancy::Unknown);
  s.map().forEach([&](Cell c, CellState st) {
    int col = 0, row = 0;
    if (v.toMap(c, col, row))
      v.map.set(col, row, st == CellState::Free ? mapio::Occupancy::Free : mapio::Occupancy::Occupied);
  });
  for (const auto& [x, y] : blocked) markOccupied(v, Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)});
  if (s.pose()) {
    int col = 0, row = 0;
    if (v.toMap(s.pose()->cell, col, row)) v.robot = plan::MapCell{col, row};
    v.heading = s.pose()->heading;
  }
  return v;
}

std::string mapText(const MapView& v) {
  if (v.bounds.empty()) return "(no map yet)\n";
  return report::renderMapText(
      v.map.width(), v.map.height(), [&](int col, int row) { return v.stateAt(col, row); }, v.robotMark());
}

bool writeMapPicture(const MapView& v, const std::string& path, std::string& error) {
  return report::writeGridPng(
      path, v.map.width(), v.map.height(), [&](int col, int row) { return v.stateAt(col, row); }, v.robotMark(), error);
}

}  // namespace nxtmap::console
