// Traversability: which cells of an OccupancyMap a plan may use, and the 8-connected moves between them.
//
// A cell is passable when it is Free (or Unknown with unknownTraversable; unknown cells are not used by
// default: the method's safety rule) and every cell within `clearanceCells` of it (a square of side
// 2*clearance+1) is passable-state and inside the map. A diagonal step needs both side cells passable
// (no corner cutting). Straight steps cost 1, diagonal steps sqrt(2) (cell units).
//
// Storage is padded by one blocked cell on every side so searches can look at a neighbour of any map cell
// without a bounds check: index(col, row) = (row + 1) * stride() + col + 1. The same cells are also kept as
// bitsets (bits(), padded coordinates x = col + 1, y = row + 1) for block-based scans.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <vector>

#include "host/mapio/OccupancyMap.hpp"
#include "host/plan/BitGrid.hpp"

namespace nxtmap::plan {

// A map cell: col to the right, row down from the top-left (as in mapio::OccupancyMap).
struct MapCell {
  int col = 0;
  int row = 0;
  bool operator==(const MapCell& o) const { return col == o.col && row == o.row; }
  bool operator!=(const MapCell& o) const { return !(*this == o); }
};

constexpr double kSqrt2 = 1.4142135623730951;

// Octile distance between two cells (the cost of the shortest move sequence on an empty grid).
inline double octile(MapCell a, MapCell b) {
  const int dx = std::abs(a.col - b.col);
  const int dy = std::abs(a.row - b.row);
  return dx < dy ? (dy - dx) + kSqrt2 * dx : (dx - dy) + kSqrt2 * dy;
}

class Traversability {
 public:
  static constexpr int kMaxClearance = 64;  // cells

  // clearanceCells: 0..kMaxClearance (clamped).
  Traversability(const mapio::OccupancyMap& map, bool unknownTraversable = false, int clearanceCells = 0);

  // Distinct for every constructed grid (copies share it): lets planners cache per-grid preprocessing.
  uint64_t id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int stride() const { return width_ + 2; }
  size_t paddedSize() const { return cells_.size(); }
  bool inside(MapCell c) const { return c.col >= 0 && c.row >= 0 && c.col < width_ && c.row < height_; }
  bool passable(MapCell c) const { return inside(c) && cells_[index(c)] != 0; }
  // Passable by padded index (the padding is never passable).
  bool open(uint32_t i) const { return cells_[i] != 0; }
  uint32_t index(MapCell c) const { return static_cast<uint32_t>((c.row + 1) * stride() + c.col + 1); }
  MapCell cellOf(uint32_t i) const {
    const int s = stride();
    return MapCell{static_cast<int>(i % static_cast<uint32_t>(s)) - 1,
                   static_cast<int>(i / static_cast<uint32_t>(s)) - 1};
  }
  // Passability as row and column bitsets, in padded coordinates.
  const BitGrid& bits() const { return bits_; }
  // One legal move from `from` by (dc, dr), each in -1..1, not both 0; both cells must be map cells or padding.
  bool canStep(MapCell from, int dc, int dr) const {
    const uint32_t i = index(from);
    const int s = stride();
    if (!open(static_cast<uint32_t>(static_cast<int>(i) + dr * s + dc))) return false;
    return dc == 0 || dr == 0 ||
           (open(static_cast<uint32_t>(static_cast<int>(i) + dc)) &&
            open(static_cast<uint32_t>(static_cast<int>(i) + dr * s)));
  }
  // True when consecutive cells of `path` are legal moves and every cell is passable; sets lengthOut.
  bool validPath(const std::vector<MapCell>& path, double& lengthOut) const;

 private:
  uint64_t id_;
  int width_;
  int height_;
  std::vector<uint8_t> cells_;  // padded, 1 = passable
  BitGrid bits_;                // the same cells as bitsets
};

}  // namespace nxtmap::plan
