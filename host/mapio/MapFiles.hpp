// MapFiles: reading and writing OccupancyMap files.
//
// Reading (one reader per format, shared with the simulator's worlds: host/sim/MovingAiFile, RosMapFile)
//  - Moving AI ".map" (type octile): '.' and 'G' free; '@', 'O', 'T', 'S', 'W' occupied; no unknown cells.
//    Resolution 0.10 m, origin (0, 0, 0). CRLF line endings tolerated.
//  - ROS map_server YAML + the PGM image it names (P5 or P2, path relative to the YAML), trinary mode:
//    shade = pixel / maxval; occ = negate ? shade : 1 - shade; occ > occupied_thresh -> Occupied,
//    occ < free_thresh -> Free, otherwise Unknown. Image row 0 is the map's top row (row 0).
//    Required keys: image, resolution, occupied_thresh, free_thresh; optional: origin [x, y, yaw] (default 0s),
//    negate (0/1, default 0), mode (only "trinary"), labels. Unknown keys are ignored. Resolution 0.01 .. 10 m,
//    origin x, y within +-100 km, yaw within +-6.3 rad (sim::RosMapFile's bounds).
//  - Optional `labels:` mapping in the YAML, NAME: [col, row] (one cell) or NAME: [col, row, width, height]
//    (a block of cells, top-left cell first); cells count like the map's (col right, row down from the top).
//  - Only regular files are read, each of a bounded size checked before reading (sim::InputFile): a .map at
//    most 18 MiB, a YAML 1 MiB, a PGM 100 MiB.
//
// Writing (ROS map_server YAML + PGM, like map_saver, 'trinary' mode)
//  - The PGM is P5, 8 bit: Occupied 0, Free 254, Unknown 205; the YAML says negate 0, occupied_thresh 0.65,
//    free_thresh 0.196 and names the image by its file name (YAML stem + ".pgm", same folder).
//  - Both files are written to temporary files in the target folder and renamed into place, so a failed save
//    leaves any previous files untouched. Saving a map loaded from a saved file reproduces the files byte for byte.
#pragma once

#include <optional>
#include <string>

#include "host/mapio/OccupancyMap.hpp"

namespace nxtmap::sim {
class World;
}

namespace nxtmap::mapio {

// Result of a load: map set on success; otherwise error names the file (and line or key) and the problem.
struct MapLoad {
  std::optional<OccupancyMap> map;
  std::string error;
};

MapLoad loadMovingAiMap(const std::string& path);
MapLoad loadRosMap(const std::string& yamlPath);
// By extension: .map -> Moving AI; .yaml / .yml -> ROS; anything else is an error.
MapLoad loadMap(const std::string& path);

// The world's cells (blocked -> Occupied, else Free) at its resolution, origin (0, 0, 0).
OccupancyMap fromWorld(const sim::World& world);

// Writes yamlPath (must end in .yaml or .yml) and the PGM beside it. False with error set on failure.
bool saveRosMap(const OccupancyMap& map, const std::string& yamlPath, std::string& error);
// The PGM file name saveRosMap writes for yamlPath (the YAML's stem + ".pgm"), without folder.
std::string pgmNameFor(const std::string& yamlPath);

// PGM pixel values the writer uses.
constexpr int kPgmOccupied = 0;
constexpr int kPgmFree = 254;
constexpr int kPgmUnknown = 205;

}  // namespace nxtmap::mapio
