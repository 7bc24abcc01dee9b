// OccupancyMap: a host-side three-state occupancy grid (free / occupied / unknown) with its size,
// resolution, origin and named cell blocks ("labels", e.g. "chair").
//
// Cell coordinates follow the rest of nxtmap (and Moving AI): col grows to the right, row grows DOWN,
// cell (0,0) is the top-left cell. In metres (ROS map_server convention) the origin is the pose of the
// lower-left corner of the map, i.e. of the bottom-left cell (col 0, row height-1); x grows with col and
// y grows with decreasing row.
//
// Files: see MapFiles.hpp (load Moving AI .map and ROS map_server YAML+PGM, save ROS YAML+PGM).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace nxtmap::mapio {

enum class Occupancy : uint8_t { Free = 0, Occupied = 1, Unknown = 2 };

// Pose of the map's lower-left corner in the map frame: metres, metres, radians (ROS `origin: [x, y, yaw]`).
struct MapOrigin {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
  bool operator==(const MapOrigin& o) const { return x == o.x && y == o.y && yaw == o.yaw; }
};

// A named block of cells: top-left cell (col, row) and its size in cells (1 x 1 for a single cell).
struct CellBlock {
  int col = 0;
  int row = 0;
  int width = 1;   // cells, >= 1
  int height = 1;  // cells, >= 1
  bool contains(int c, int r) const { return c >= col && r >= row && c < col + width && r < row + height; }
  bool operator==(const CellBlock& o) const {
    return col == o.col && row == o.row && width == o.width && height == o.height;
  }
};

class OccupancyMap {
 public:
  static constexpr int kMaxSide = 4096;  // largest width or height, cells

  // An empty 0 x 0 map.
  OccupancyMap() = default;
  // width, height: 1..kMaxSide cells (throws std::invalid_argument otherwise); resolutionM > 0.
  OccupancyMap(int width, int height, Occupancy fill = Occupancy::Unknown, double resolutionM = 0.10,
               MapOrigin origin = {});

  int width() const { return width_; }
  int height() const { return height_; }
  double resolutionM() const { return resolutionM_; }  // metres per cell side
  const MapOrigin& origin() const { return origin_; }
  void setOrigin(const MapOrigin& origin) { origin_ = origin; }

  bool inside(int col, int row) const { return col >= 0 && row >= 0 && col < width_ && row < height_; }
  // The cell's state; precondition inside(col, row).
  Occupancy at(int col, int row) const { return cells_[index(col, row)]; }
  // The cell's state, or `outside` for a cell outside the map.
  Occupancy stateOr(int col, int row, Occupancy outside) const { return inside(col, row) ? at(col, row) : outside; }
  bool isFree(int col, int row) const { return stateOr(col, row, Occupancy::Occupied) == Occupancy::Free; }
  // Precondition inside(col, row).
  void set(int col, int row, Occupancy state) { cells_[index(col, row)] = state; }
  size_t count(Occupancy state) const;

  // Labels: NAME -> block. Names are 1..64 characters of [A-Za-z0-9_-] starting with a letter (not "null"
  // in any case, so they stay plain YAML keys). A label's block must lie inside the map.
  const std::map<std::string, CellBlock>& labels() const { return labels_; }
  // False (and no change) for a bad name or a block not inside the map; otherwise adds or replaces it.
  bool setLabel(const std::string& name, const CellBlock& block);
  void removeLabel(const std::string& name) { labels_.erase(name); }
  static bool validLabelName(const std::string& name);

  // Same cells, size, resolution, origin and labels.
  bool operator==(const OccupancyMap& o) const;
  bool operator!=(const OccupancyMap& o) const { return !(*this == o); }

 private:
  size_t index(int col, int row) const {
    return static_cast<size_t>(row) * static_cast<size_t>(width_) + static_cast<size_t>(col);
  }

  int width_ = 0;
  int height_ = 0;
  double resolutionM_ = 0.10;
  MapOrigin origin_;
  std::vector<Occupancy> cells_;  // row-major, row 0 = top
  std::map<std::string, CellBlock> labels_;
};

}  // namespace nxtmap::mapio
