// WorldFile: nxtmap's own YAML world format, for hand-made rooms with furniture (worlds/rooms/README.md).
//
//   nxtmap_world: 1                # required first: the format's version; tells the file from a ROS map YAML
//   name: living room              # optional (default: the file's name without its folder and extension)
//   outline:                       # required: the room's walls; the inside is free, the outside solid
//     polygon: [[0, 0], [4.8, 0], [4.8, 3.8], [0, 3.8]]
//     surface: hard                # optional: hard (default), soft or thin
//   obstacles:                     # optional: each entry is one polygon, circle or wall
//     - name: sofa                 # optional label, used in messages
//       polygon: [[0.4, 0.03], [2.4, 0.03], [2.4, 0.93], [0.4, 0.93]]   # solid furniture
//       surface: soft              # default hard
//     - circle: [1.5, 2.0]         # a solid disc (a table leg): its centre ...
//       radius: 0.0125             # ... and radius; surface default thin
//     - wall: [[1.0, 3.7], [2.8, 3.7]]   # an open line of >= 2 points (a curtain); surface default hard
//       surface: soft
//   start: {x: 2.4, y: 1.9, yaw: 90}     # optional robot start; yaw in degrees
//   transform: {rotate_deg: 10, offset: [0.0667, 0.0667]}                # optional
//
// Units and frames (as ROS): metres, x to the right, y UP; yaw counter-clockwise from +x. A file point
// (x, y) becomes the plane point (100 x, -100 y) cm (Scene: y down); a yaw becomes the compass heading
// 90 - yaw (normalised to 0 .. 360). Polygons are closed implicitly (a last point repeating the first is
// allowed). Solid space follows Scene: even-odd over the outline and the obstacle polygons, discs and walls
// solid themselves.
//
// transform: the room's geometry (outline and obstacles) is turned by rotate_deg counter-clockwise about the
// file's origin (0, 0), then moved by offset [dx, dy] metres. The start is NOT moved: it is where the robot
// is set down on the plane, and the room is turned and shifted under it. So a square room drawn around
// (0, 0) with the start at (0, 0) and yaw 90 becomes, with one line, a room whose walls stand 10 degrees
// off the robot's heading and a third of a cell off its grid (worlds/rooms/square-turned.yaml).
//
// Checks (each refusal is one line "FILE[:LINE]: WHERE: problem", LINE 1-based, WHERE e.g. "obstacles[2]
// (sofa)", index from 0): the marker key; unknown or repeated keys; numbers finite, coordinates within
// +-kMaxCoordM, the outline within kMaxExtentM a side, counts within the kMax bounds below; polygons of >= 3
// distinct points, with an area, not crossing themselves (every pair of sides); walls of >= 2 distinct
// points; 0 < radius <= kMaxRadiusM; surface names; obstacles inside the outline (touching allowed),
// obstacle polygons not overlapping one another (the even-odd rule would make their overlap free); the start
// inside the outline and not inside or on an obstacle. Whether the robot's body fits at the start is the
// caller's check.
#pragma once

#include "host/sim/Scene.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

namespace nxtmap::sim {

constexpr size_t kMaxWorldFileBytes = size_t{1} << 20;  // the YAML file, bytes
constexpr double kMaxCoordM = 1000.0;                   // |x|, |y| of any point and |dx|, |dy| of the offset, metres
constexpr double kMaxExtentM = 200.0;                   // the outline's width and height, metres (a house, not a town)
constexpr double kMaxRadiusM = 5.0;                     // a circle's radius, metres
constexpr size_t kMaxObstacles = 2000;                  // entries under obstacles
constexpr size_t kMaxPolygonPoints = 1000;              // points of one polygon or wall
constexpr size_t kMaxWorldPoints = 10000;  // polygon and wall points in all (keeps the checks, which compare
                                           // sides pairwise, well under a second; a furnished room has ~100)
constexpr size_t kMaxNameChars = 100;      // the world's and an obstacle's name

struct WorldSpec {
  std::string name;
  std::shared_ptr<const Scene> scene;  // finished (Scene::finish called)
  bool hasStart = false;
  Vec2 startCm{0.0, 0.0};        // plane point, cm (valid when hasStart)
  double startHeadingDeg = 0.0;  // compass, clockwise from north, 0 .. 360 (valid when hasStart)
};

struct WorldFileLoad {
  std::optional<WorldSpec> world;  // set on success
  std::string error;               // otherwise: one line naming the file, the element and the problem
};

// Reads the file (a regular file of at most kMaxWorldFileBytes: readInputFile) and parses it.
WorldFileLoad readWorldFile(const std::string& path);
// Parses a document; `name` labels the messages (a path) and gives the default world name.
WorldFileLoad parseWorldFile(const std::string& text, const std::string& name);
// True if the text is a YAML mapping with the marker key nxtmap_world (so a .yaml path can be sent to
// readWorldFile rather than to the ROS map reader). Never throws.
bool looksLikeWorldFile(const std::string& text);

}  // namespace nxtmap::sim
