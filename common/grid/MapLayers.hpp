#pragma once
#include <cstddef>
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/PackedCells.hpp"
#include "common/grid/RoomGrid.hpp"

namespace nxtmap {

// Everything the robot knows about one room, over caller-owned storage (see MapStorage):
//  - the three-state RoomGrid (2 bits per cell), the map everyone reads;
//  - evidence (4 bits per cell): a saturating count, -7 (surely free) .. +7 (surely occupied),
//    from which the grid's state is derived: Occupied when > 0, Free otherwise, Unknown when the
//    cell was never observed. Without noise every observation agrees, so the grid is exactly the
//    method's three-state map; with noise, later readings can correct an earlier wrong one;
//  - read memory (4 bits per cell): the directions already read from that cell (the method's
//    "remember where it stopped reading", so the same stretch is not read again);
//  - diagonal memory (2 bits per cell): the diagonal moves already travelled (stop heuristic).
class MapLayers {
 public:
  struct Storage {
    uint8_t* grid;       // packedBytes(w, h, 2)
    uint8_t* evidence;   // packedBytes(w, h, 4)
    uint8_t* reads;      // packedBytes(w, h, 4)
    uint8_t* diagonals;  // packedBytes(w, h, 2)
  };
  MapLayers(const Storage& storage, int16_t width, int16_t height);

  void clear();

  RoomGrid& grid() { return grid_; }
  const RoomGrid& grid() const { return grid_; }
  CellState at(Cell c) const { return grid_.at(c); }

  // One observation of a cell as free / as occupied. Fail only when the grid is full.
  [[nodiscard]] bool observeFree(Cell c);
  [[nodiscard]] bool observeOccupied(Cell c);
  // The robot stood in the cell: certainly free. A move into the cell was blocked: certainly occupied.
  [[nodiscard]] bool markVisited(Cell c);
  [[nodiscard]] bool markBlocked(Cell c);
  // A move into the cell was blocked: certainly occupied, unless the cell is surely free (the robot stood in it, or
  // saw it free again and again): then as three echoes from it, still free. A body that grazes a wall beside its
  // way is blocked too, and a cell it drove through cut off as a wall splits the map; a second blocked move there
  // makes the cell certain.
  [[nodiscard]] bool observeBlocked(Cell c);
  int8_t evidence(Cell c) const { return static_cast<int8_t>(evidence_.at(c)) - 8; }

  bool wasRead(Cell c, Dir d) const { return (readDirs(c) >> static_cast<int>(d)) & 1u; }
  uint8_t readDirs(Cell c) const { return reads_.at(c); }  // bit d set: Dir d was read from c
  void setRead(Cell c, Dir d) { reads_.set(c, static_cast<uint8_t>(reads_.at(c) | (1u << static_cast<int>(d)))); }
  // Forgets a cell in every layer: unknown, no evidence, never read from, no diagonal used from it.
  void forget(Cell c);
  // Forgets the directions in `dirs` (bit d set: Dir d) as read from c, so they are read again.
  void forgetReads(Cell c, uint8_t dirs) { reads_.set(c, static_cast<uint8_t>(reads_.at(c) & ~dirs & 0xFu)); }

  // Diagonal moves between c and c + (sx, sy), sx, sy = +-1, in either direction.
  bool diagonalUsed(Cell c, int sx, int sy) const;
  void setDiagonalUsed(Cell c, int sx, int sy);

  // The method's restructuring, applied to every layer together. Returns the old coordinates
  // of the new origin (the room's lower-left corner).
  Cell restructure();

 private:
  [[nodiscard]] bool setEvidence(Cell c, int e);
  static void diagonalSlot(Cell c, int sx, int sy, Cell& base, uint8_t& bit);

  RoomGrid grid_;
  PackedCells<4> evidence_;
  PackedCells<4> reads_;
  PackedCells<2> diagonals_;
};

// Storage for a MapLayers of a fixed capacity, sized at compile time.
template <int W, int H>
struct MapStorage {
  static_assert(isPowerOfTwo(W) && isPowerOfTwo(H), "capacities are powers of two");
  static_assert(W <= 128 && H <= 128, "travel planning indexes states in 16 bits");
  uint8_t grid[packedBytes(W, H, 2)];
  uint8_t evidence[packedBytes(W, H, 4)];
  uint8_t reads[packedBytes(W, H, 4)];
  uint8_t diagonals[packedBytes(W, H, 2)];
  MapLayers::Storage view() { return MapLayers::Storage{grid, evidence, reads, diagonals}; }
  static constexpr int16_t kWidth() { return W; }
  static constexpr int16_t kHeight() { return H; }
};

}  // namespace nxtmap
