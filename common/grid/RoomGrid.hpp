#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/CellState.hpp"
#include "common/grid/PackedCells.hpp"

namespace nxtmap {

// The room map: three states in 2 bits per cell over caller-owned storage of a fixed capacity
// (powers of two, e.g. 64x64 = 1 KiB on the brick). The start cell is the origin and is free;
// the map grows into all four quadrants by wrapping. The window is the bounding box of every
// cell ever set; a set() that would make it wider or taller than the capacity fails, so
// wrapped coordinates never alias. When mapping ends, restructure() moves the origin to the
// window's lower-left corner (the method's restructuring) so all coordinates are non-negative.
class RoomGrid {
 public:
  // `storage`: packedBytes(capacityWidth, capacityHeight, 2) bytes, owned by the caller.
  RoomGrid(uint8_t* storage, int16_t capacityWidth, int16_t capacityHeight);

  // Forgets everything: all cells unknown, empty window.
  void clear();

  // State of a cell; Unknown for any cell outside the window.
  CellState at(Cell c) const;
  bool isFree(Cell c) const { return at(c) == CellState::Free; }
  bool isOccupied(Cell c) const { return at(c) == CellState::Occupied; }
  bool isUnknown(Cell c) const { return at(c) == CellState::Unknown; }

  // Sets a cell. Fails (changing nothing) when the window would exceed the capacity.
  [[nodiscard]] bool set(Cell c, CellState s);
  // Whether set(c, ...) would succeed.
  bool fits(Cell c) const;
  // Whether the window spans the whole capacity along x or y (a set() beyond it fails that way).
  bool full() const { return window_.width() >= cells_.width() || window_.height() >= cells_.height(); }
  // Forgets a cell (Unknown again). The window keeps its extent until shrink().
  void forget(Cell c) {
    if (window_.contains(c)) cells_.set(c, static_cast<uint8_t>(CellState::Unknown));
  }
  // Shrinks the window to the bounding box of the cells still known (after forget()).
  void shrink();

  Bounds window() const { return window_; }
  int16_t capacityWidth() const { return cells_.width(); }
  int16_t capacityHeight() const { return cells_.height(); }

  // Number of cells in the window with the given state.
  int32_t count(CellState s) const;

  // Moves the origin to the window's lower-left corner: every cell (x, y) becomes
  // (x - minX, y - minY). Returns the translation applied (the old coordinates of the new origin).
  Cell restructure();

  // Storage on the torus, for layers that must move together with the grid (see MapLayers).
  const PackedCells<2>& cells() const { return cells_; }

 private:
  PackedCells<2> cells_;
  Bounds window_;
};

}  // namespace nxtmap
