// RosMapFile: the one reader of ROS map_server maps (a YAML file and the PGM image it names), shared by the
// simulator's worlds (sim::World: unknown cells blocked) and the planner's and houses' maps
// (mapio::loadRosMap: three states, origin, labels). Every rule of the format lives here:
//
//  - Required keys: image, resolution, occupied_thresh, free_thresh; optional: origin [x, y, yaw] (default 0s),
//    negate (0/1, true/false; default 0), mode (only "trinary"), labels. Unknown keys are ignored.
//  - The image (P5 or P2 PGM, readPgm) is named relative to the YAML's folder unless absolute.
//  - Trinary mode: shade = pixel / maxval; occ = negate ? shade : 1 - shade; occ > occupied_thresh ->
//    Occupied, occ < free_thresh -> Free, otherwise Unknown. Image row 0 is the map's top row (row 0).
//  - Thresholds: 0 <= free_thresh <= occupied_thresh <= 1.
//  - resolution: kMinResolutionM .. kMaxResolutionM metres per cell; origin x, y within +-kMaxOriginM metres,
//    yaw within +-kMaxOriginYawRad. Non-finite numbers are refused. (The simulator accepts a narrower range
//    of resolutions: World::resolutionProblem.)
//  - labels: a mapping NAME: [col, row] (one cell) or NAME: [col, row, width, height] of whole numbers;
//    whether a name is valid and the block lies inside the map is the map's business (mapio::OccupancyMap).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

// A map resolution from 1 cm to 10 m per cell: the sonar reads whole centimetres, so a finer map holds
// nothing our robot could make or use, and a cell coarser than 10 m is no map of a room or a house. With the
// origin's bound it keeps the origin within +-1e7 cells of the map, far inside an int.
constexpr double kMinResolutionM = 0.01;
constexpr double kMaxResolutionM = 10.0;
constexpr double kMaxOriginM = 100000.0;              // |origin x|, |origin y|, metres (100 km)
constexpr double kMaxOriginYawRad = 6.3;              // |origin yaw|, radians (a whole turn either way)
constexpr size_t kMaxRosYamlBytes = size_t{1} << 20;  // the YAML file, bytes (labels included)

enum class RosCell : uint8_t { Free = 0, Occupied = 1, Unknown = 2 };

struct RosMapLabel {
  std::string name;
  int col = 0;
  int row = 0;
  int width = 1;   // cells, as written (checked by the map)
  int height = 1;  // cells, as written (checked by the map)
};

struct RosMapFile {
  int width = 0;                    // cells, 1..4096 (the image's size)
  int height = 0;                   // cells, 1..4096
  double resolutionM = 0.10;        // metres per cell side
  double originX = 0.0;             // metres: the map's lower-left corner
  double originY = 0.0;             // metres
  double originYaw = 0.0;           // radians
  std::vector<RosCell> cells;       // row-major, row 0 = top
  std::vector<RosMapLabel> labels;  // in file order
};

// Reads the YAML and its image; nullopt with `error` ("YAMLPATH: <problem>", naming the key or the image).
std::optional<RosMapFile> readRosMapFile(const std::string& yamlPath, std::string& error);

}  // namespace nxtmap::sim
