// MovingAiFile: the one reader of Moving AI ".map" grids, shared by the simulator's worlds (sim::World) and
// the planner's maps (mapio::loadMovingAiMap).
//
// Format: "type octile", "height H", "width W" (either order), "map", then H rows of W characters.
// '.' and 'G' are free; '@', 'O', 'T', 'S', 'W' blocked; anything else is an error. CRLF tolerated; blank
// lines after the rows are ignored. The format has no resolution: its cells are kMovingAiResolutionM.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

constexpr double kMovingAiResolutionM = 0.10;  // metres per cell side (the published experiments' cell)
// Largest file read, bytes: the largest grid (World::kMaxSide = 4096 rows of 4096 cells with CRLF line ends,
// 16.0 MiB) with 2 MiB to spare for the header and trailing blank lines. Checked before reading.
constexpr size_t kMaxMovingAiBytes = size_t{18} << 20;

struct MovingAiGrid {
  int width = 0;                 // cells, 1..World::kMaxSide
  int height = 0;                // cells, 1..World::kMaxSide
  std::vector<uint8_t> blocked;  // row-major, row 0 = the file's first map row; 1 = blocked, 0 = free
};

// Reads and checks the file; nullopt with `error` naming the file, the line and the problem.
std::optional<MovingAiGrid> readMovingAiFile(const std::string& path, std::string& error);

}  // namespace nxtmap::sim
