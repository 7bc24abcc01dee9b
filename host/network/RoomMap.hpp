// RoomMap: one room's three-state map in the room's own frame (explorer convention: x right,
// y up, the entrance cell at (0, 0)). Cells outside the stored box are unknown.
#pragma once

#include <cstdint>
#include <vector>

#include "common/grid/Cell.hpp"
#include "common/grid/CellState.hpp"
#include "common/grid/RoomGrid.hpp"

namespace nxtmap::network {

class RoomMap {
 public:
  RoomMap() = default;
  // A box of unknown cells: minX, minY its lowest cell, width x height cells (>= 0).
  RoomMap(int minX, int minY, int width, int height);
  // A copy of the grid's window.
  static RoomMap fromGrid(const RoomGrid& grid);

  int minX() const { return minX_; }
  int minY() const { return minY_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int maxX() const { return minX_ + width_ - 1; }
  int maxY() const { return minY_ + height_ - 1; }
  bool inside(Cell c) const { return c.x >= minX_ && c.y >= minY_ && c.x <= maxX() && c.y <= maxY(); }
  CellState at(Cell c) const { return inside(c) ? cells_[index(c)] : CellState::Unknown; }
  bool isFree(Cell c) const { return at(c) == CellState::Free; }
  // Precondition inside(c).
  void set(Cell c, CellState s) { cells_[index(c)] = s; }
  int count(CellState s) const;
  // The first occupied cell along d from `from` (1 = the adjacent cell), looking at most maxCells
  // out; 0 when there is none.
  int firstOccupied(Cell from, Dir d, int maxCells) const;
  bool operator==(const RoomMap& o) const;

 private:
  size_t index(Cell c) const {
    return static_cast<size_t>(c.y - minY_) * static_cast<size_t>(width_) + static_cast<size_t>(c.x - minX_);
  }
  int minX_ = 0, minY_ = 0, width_ = 0, height_ = 0;
  std::vector<CellState> cells_;  // row-major from (minX, minY)
};

}  // namespace nxtmap::network
