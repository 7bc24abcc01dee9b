// WorldDraft: a world file as read (WorldFile), in the file's metres and frame, before its shapes are
// checked against one another and turned into a Scene. WorldFile reads the YAML into a draft (every number
// finite and in range, every key known); checkShapes, buildWorld and checkStart do the rest.
#pragma once

#include "host/sim/Scene.hpp"
#include "host/sim/WorldFile.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace nxtmap::sim {

struct DraftShape {
  enum class Kind { Polygon, Circle, Wall };
  Kind kind = Kind::Polygon;
  std::string at;            // "FILE:LINE" of the shape's node
  std::string label;         // "outline" or "obstacles[2] (sofa)"
  std::vector<Vec2> points;  // metres, file frame (y up), as written; a circle: its centre only
  std::vector<size_t> kept;  // checkShapes: indices into points without repeats
  double radiusM = 0.0;      // a circle's radius, metres
  Surface surface = Surface::Hard;

  std::string where() const { return at + ": " + label; }  // message prefix
};

struct WorldDraft {
  std::string name;
  DraftShape outline;  // a Polygon
  std::vector<DraftShape> obstacles;
  bool hasStart = false;
  std::string startWhere;    // message prefix: "FILE:LINE: start"
  Vec2 startM{0.0, 0.0};     // metres, file frame, on the plane (not moved by the transform)
  double startYawDeg = 0.0;  // counter-clockwise from +x
  double rotateDeg = 0.0;    // transform: counter-clockwise about (0, 0), then ...
  Vec2 offsetM{0.0, 0.0};    // ... moved by this, metres
};

// "" or the first problem of one shape or between shapes ("WHERE: problem"); fills each shape's `kept`.
std::string checkShapes(WorldDraft& draft);

// The world (scene finished, start converted to the plane); the draft has passed checkShapes.
WorldSpec buildWorld(const WorldDraft& draft);

// "" or why the start cannot be used: outside or on the outline, inside or on an obstacle (Scene::solidAt).
std::string checkStart(const WorldDraft& draft, const WorldSpec& world);

// File point (metres, y up) -> plane point (cm, y down).
inline Vec2 fileToPlaneCm(const Vec2& m) { return Vec2(100.0 * m.x(), -100.0 * m.y()); }

}  // namespace nxtmap::sim
