#include "host/sim/WorldFile.hpp"

#include "host/sim/InputFile.hpp"
#include "host/sim/WorldDraft.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <set>

namespace nxtmap::sim {

namespace {

// A refusal while reading: the whole message, ready to return.
struct Refusal {
  std::string message;
};

constexpr double kMaxAngleDeg = 360.0;  // |yaw|, |rotate_deg|

// Reads one document into a draft; throws Refusal.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  WorldDraft read(const YAML::Node& doc) {
    if (!doc.IsMap()) refuse(file_, "not an nxtmap world file: not a YAML mapping of keys");
    if (!doc["nxtmap_world"]) {
      if (doc["image"]) {
        refuse(file_,
               "not an nxtmap world file: it has 'image:', so it is a ROS map_server map "
               "(a world file starts with 'nxtmap_world: 1')");
      }
      refuse(file_, "not an nxtmap world file (no 'nxtmap_world: 1' key)");
    }
    knownKeys(doc, "the top level", {"nxtmap_world", "name", "outline", "obstacles", "start", "transform"});
    const YAML::Node version = doc["nxtmap_world"];
    if (!version.IsScalar() || version.Scalar() != "1") {
      refuse(at(version), "'nxtmap_world' must be 1 (the only version of the format), not '" + shown(version) + "'");
    }
    WorldDraft d;
    d.name = doc["name"] ? text(doc["name"], "name") : std::filesystem::path(file_).stem().string();
    if (!doc["outline"]) refuse(file_, "missing 'outline' (the room's walls: outline: {polygon: [[x, y], ...]})");
    d.outline = outline(doc["outline"]);
    if (doc["obstacles"]) obstacles(doc["obstacles"], d.obstacles);
    if (doc["start"]) start(doc["start"], d);
    if (doc["transform"]) transform(doc["transform"], d);
    return d;
  }

 private:
  [[noreturn]] static void refuse(const std::string& where, const std::string& problem) {
    throw Refusal{where + ": " + problem};
  }

  std::string at(const YAML::Node& n) const { return file_ + ":" + std::to_string(n.Mark().line + 1); }

  static std::string shown(const YAML::Node& n) {
    if (!n.IsScalar()) return n.IsSequence() ? "a list" : (n.IsMap() ? "a mapping" : "nothing");
    return n.Scalar().size() > 40 ? n.Scalar().substr(0, 40) + "..." : n.Scalar();
  }

  // Every key a plain word, known and given once.
  void knownKeys(const YAML::Node& map, const std::string& where, std::initializer_list<const char*> known) const {
    std::string list;
    for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    std::set<std::string> seen;
    for (const auto& entry : map) {
      const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
      bool ok = false;
      for (const char* k : known) ok = ok || key == k;
      if (!ok) refuse(at(entry.first), "unknown key '" + key + "' in " + where + " (known: " + list + ")");
      if (!seen.insert(key).second) refuse(at(entry.first), "key '" + key + "' given twice in " + where);
    }
  }

  std::string text(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar() || n.Scalar().empty() || n.Scalar().size() > kMaxNameChars) {
      refuse(at(n), "'" + what + "' must be a text of 1 to " + std::to_string(kMaxNameChars) + " characters");
    }
    for (const char c : n.Scalar()) {
      if (static_cast<unsigned char>(c) < 0x20) refuse(at(n), "'" + what + "' must be one line of text");
    }
    return n.Scalar();
  }

  double number(const YAML::Node& n, const std::string& what, double bound) const {
    double v = 0.0;
    bool ok = n.IsScalar();
    if (ok) {
      try {
        v = n.as<double>();
      } catch (const YAML::Exception&) {
        ok = false;
      }
    }
    if (!ok || !std::isfinite(v) || std::fabs(v) > bound) {
      char range[32];
      std::snprintf(range, sizeof range, "%g", bound);
      refuse(at(n), what + " must be a finite number within +-" + range + ", not '" + shown(n) + "'");
    }
    return v;
  }

  Vec2 point(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence() || n.size() != 2) refuse(at(n), what + " must be a point [x, y] in metres");
    return Vec2(number(n[0], what + " x", kMaxCoordM), number(n[1], what + " y", kMaxCoordM));
  }

  std::vector<Vec2> points(const YAML::Node& n, const std::string& what) {
    if (!n.IsSequence()) refuse(at(n), what + " must be a list of points [[x, y], ...] in metres");
    if (n.size() > kMaxPolygonPoints) {
      refuse(at(n),
             what + " has " + std::to_string(n.size()) + " points; at most " + std::to_string(kMaxPolygonPoints));
    }
    pointsRead_ += n.size();
    if (pointsRead_ > kMaxWorldPoints) {
      refuse(at(n), "the world has more than " + std::to_string(kMaxWorldPoints) + " points in all");
    }
    std::vector<Vec2> out;
    for (size_t i = 0; i < n.size(); ++i) out.push_back(point(n[i], what + "[" + std::to_string(i) + "]"));
    return out;
  }

  Surface surface(const YAML::Node& entry, const std::string& label, Surface fallback) const {
    const YAML::Node n = entry["surface"];
    if (!n) return fallback;
    const std::optional<Surface> s = n.IsScalar() ? surfaceFromName(n.Scalar()) : std::nullopt;
    if (!s) refuse(at(n), label + ": unknown surface '" + shown(n) + "' (known: hard, soft, thin)");
    return *s;
  }

  DraftShape outline(const YAML::Node& n) {
    if (!n.IsMap()) refuse(at(n), "'outline' must be a mapping {polygon: [[x, y], ...], surface: hard}");
    knownKeys(n, "outline", {"polygon", "surface"});
    if (!n["polygon"]) refuse(at(n), "outline: missing 'polygon' (the room's corners [[x, y], ...])");
    DraftShape s;
    s.at = at(n);
    s.label = "outline";
    s.points = points(n["polygon"], "outline polygon");
    s.surface = surface(n, s.label, Surface::Hard);
    return s;
  }

  void obstacles(const YAML::Node& n, std::vector<DraftShape>& out) {
    if (n.IsNull()) return;
    if (!n.IsSequence()) refuse(at(n), "'obstacles' must be a list of polygon, circle and wall entries");
    if (n.size() > kMaxObstacles) {
      refuse(at(n),
             "'obstacles' has " + std::to_string(n.size()) + " entries; at most " + std::to_string(kMaxObstacles));
    }
    for (size_t i = 0; i < n.size(); ++i) out.push_back(obstacle(n[i], i));
  }

  DraftShape obstacle(const YAML::Node& n, size_t index) {
    DraftShape s;
    s.at = at(n);
    s.label = "obstacles[" + std::to_string(index) + "]";
    if (!n.IsMap()) refuse(s.where(), "must be a mapping with one of polygon, circle, wall");
    knownKeys(n, s.label, {"name", "polygon", "circle", "radius", "wall", "surface"});
    if (n["name"]) s.label += " (" + text(n["name"], s.label + " name") + ")";
    const int kinds = (n["polygon"] ? 1 : 0) + (n["circle"] ? 1 : 0) + (n["wall"] ? 1 : 0);
    if (kinds != 1) refuse(s.where(), "needs exactly one of 'polygon', 'circle', 'wall'");
    if (n["radius"] && !n["circle"]) refuse(s.where(), "'radius' belongs to a circle");
    if (n["polygon"]) {
      s.at = at(n["polygon"]);
      s.points = points(n["polygon"], s.label + " polygon");
      s.surface = surface(n, s.label, Surface::Hard);
    } else if (n["wall"]) {
      s.kind = DraftShape::Kind::Wall;
      s.at = at(n["wall"]);
      s.points = points(n["wall"], s.label + " wall");
      s.surface = surface(n, s.label, Surface::Hard);
    } else {
      s.kind = DraftShape::Kind::Circle;
      s.at = at(n["circle"]);
      s.points = {point(n["circle"], s.label + " circle centre")};
      if (!n["radius"]) refuse(s.where(), "circle needs a 'radius' in metres");
      s.radiusM = number(n["radius"], "radius", kMaxCoordM);
      if (!(s.radiusM > 0.0) || s.radiusM > kMaxRadiusM) {
        char buf[80];
        std::snprintf(buf, sizeof buf, "circle radius must be > 0 and at most %g m, not %g", kMaxRadiusM, s.radiusM);
        refuse(at(n["radius"]), s.label + ": " + buf);
      }
      s.surface = surface(n, s.label, Surface::Thin);
    }
    return s;
  }

  void start(const YAML::Node& n, WorldDraft& d) const {
    d.startWhere = at(n) + ": start";
    if (!n.IsMap() || !n["x"] || !n["y"] || !n["yaw"]) {
      refuse(d.startWhere, "must be {x: metres, y: metres, yaw: degrees counter-clockwise from +x}");
    }
    knownKeys(n, "start", {"x", "y", "yaw"});
    d.hasStart = true;
    d.startM = Vec2(number(n["x"], "start x", kMaxCoordM), number(n["y"], "start y", kMaxCoordM));
    d.startYawDeg = number(n["yaw"], "start yaw", kMaxAngleDeg);
  }

  void transform(const YAML::Node& n, WorldDraft& d) const {
    if (!n.IsMap()) refuse(at(n), "'transform' must be {rotate_deg: degrees, offset: [dx, dy]}");
    knownKeys(n, "transform", {"rotate_deg", "offset"});
    if (n["rotate_deg"]) d.rotateDeg = number(n["rotate_deg"], "rotate_deg", kMaxAngleDeg);
    if (n["offset"]) d.offsetM = point(n["offset"], "offset");
  }

  std::string file_;
  size_t pointsRead_ = 0;  // polygon and wall points so far (kMaxWorldPoints)
};

}  // namespace

WorldFileLoad parseWorldFile(const std::string& text, const std::string& name) {
  WorldFileLoad out;
  try {
    WorldDraft draft = Reader(name).read(YAML::Load(text));
    if (std::string why = checkShapes(draft); !why.empty()) return WorldFileLoad{std::nullopt, why};
    WorldSpec world = buildWorld(draft);
    if (std::string why = checkStart(draft, world); !why.empty()) return WorldFileLoad{std::nullopt, why};
    out.world = std::move(world);
  } catch (const Refusal& r) {
    out.error = r.message;
  } catch (const YAML::Exception& e) {
    out.error = name + ": " + e.what();
  }
  return out;
}

WorldFileLoad readWorldFile(const std::string& path) {
  WorldFileLoad out;
  const std::optional<std::string> text = readInputFile(path, kMaxWorldFileBytes, "world file", out.error);
  if (!text) return out;
  return parseWorldFile(*text, path);
}

bool looksLikeWorldFile(const std::string& text) {
  try {
    const YAML::Node doc = YAML::Load(text);
    return doc.IsMap() && doc["nxtmap_world"];
  } catch (const YAML::Exception&) {
    return false;
  }
}

}  // namespace nxtmap::sim
