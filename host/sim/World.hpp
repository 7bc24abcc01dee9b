// World: the true occupancy of the simulated environment, one flag per square cell.
// Coordinates follow Moving AI: col grows to the right, row grows DOWN (row 0 = top line of the file).
#pragma once

#include "host/sim/MovingAiFile.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

class World;

// Result of loading a world file: world set on success, otherwise error names the file (and line) and problem.
struct WorldLoad;

class World {
 public:
  static constexpr int kMaxSide = 4096;  // largest accepted width or height, cells
  // Cells the simulated robot can map, whole centimetres a side: its geometry (RangeGeometry, the pilot)
  // counts whole centimetres per cell, so a resolution between them (0.125 m) puts the robot off its
  // cells a little more with every move. Below 4 cm a wall two cells away lies inside the sonar's 5 cm
  // minimum range and reads as the adjacent cell; above 169 cm even the longest trusted range (2.54 m) no
  // longer covers 1.5 cells, so no reading proves a neighbour free. (A shorter --range-m narrows the top
  // further; the commands check it: the range must cover 1.5 cells.)
  static constexpr int kMinCellCm = 4;
  static constexpr int kMaxCellCm = 169;

  int width() const { return width_; }                 // cells, 1..kMaxSide
  int height() const { return height_; }               // cells, 1..kMaxSide
  double resolutionM() const { return resolutionM_; }  // metres per cell side, > 0 (loaded: resolutionProblem "")
  std::string name() const { return name_; }           // file stem, or "rows" for fromRows
  bool inside(int col, int row) const { return col >= 0 && row >= 0 && col < width_ && row < height_; }
  // True for obstacles and for every cell outside the map.
  bool blocked(int col, int row) const {
    return !inside(col, row) ||
           cells_[static_cast<size_t>(row) * static_cast<size_t>(width_) + static_cast<size_t>(col)] != 0;
  }

  // "" when the simulator can use cells of resolutionM metres (kMinCellCm..kMaxCellCm whole centimetres),
  // otherwise why not.
  static std::string resolutionProblem(double resolutionM);

  // Moving AI ".map" (MovingAiFile): '.'/'G' free; '@','O','T','S','W' blocked. CRLF tolerated.
  static WorldLoad loadMovingAi(const std::string& path, double resolutionM = kMovingAiResolutionM);
  // ROS map_server YAML (trinary mode) and the P5/P2 PGM it names (RosMapFile); unknown cells become
  // blocked; the origin and labels play no part.
  static WorldLoad loadRosYaml(const std::string& yamlPath);
  // By extension: .map -> Moving AI, .yaml/.yml -> ROS; otherwise "unknown world format".
  static WorldLoad load(const std::string& path);
  // For tests: '#' or '@' blocked, '.' or ' ' free (anything else blocked); short rows padded free.
  static World fromRows(const std::vector<std::string>& rows, double resolutionM = 0.10);
  // From computed cells (a scene's truth raster): width, height 1..kMaxSide; cells row-major
  // width * height, nonzero = blocked (stored as 1).
  static World fromCells(int width, int height, double resolutionM, std::string name, std::vector<uint8_t> cells);

 private:
  World(int width, int height, double resolutionM, std::string name, std::vector<uint8_t> cells);

  int width_;
  int height_;
  double resolutionM_;
  std::string name_;
  std::vector<uint8_t> cells_;  // row-major, 1 = blocked
};

struct WorldLoad {
  std::optional<World> world;
  std::string error;
};

}  // namespace nxtmap::sim
