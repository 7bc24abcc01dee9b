#include "host/mapio/MapFiles.hpp"

#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "host/fileio/AtomicFile.hpp"
#include "host/sim/PgmImage.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::mapio {
namespace {

namespace fs = std::filesystem;

MapLoad fail(std::string message) { return MapLoad{std::nullopt, std::move(message)}; }

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Shortest text that reads back as the same double.
std::string formatDouble(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

bool readFlag(const YAML::Node& node, bool& out) {
  const std::string s = node.as<std::string>();
  if (s == "0" || s == "false" || s == "False") {
    out = false;
    return true;
  }
  if (s == "1" || s == "true" || s == "True") {
    out = true;
    return true;
  }
  return false;
}

// A finite double from a scalar; false if it is not one.
bool readDouble(const YAML::Node& node, double& out) {
  if (!node.IsScalar()) return false;
  try {
    out = node.as<double>();
  } catch (const YAML::Exception&) {
    return false;
  }
  return std::isfinite(out);
}

bool readInt(const YAML::Node& node, int& out) {
  if (!node.IsScalar()) return false;
  const std::string s = node.Scalar();
  const auto res = std::from_chars(s.data(), s.data() + s.size(), out);
  return res.ec == std::errc() && res.ptr == s.data() + s.size();
}

// Reads `labels:` into the map; returns an error text or "".
std::string readLabels(const YAML::Node& node, OccupancyMap& map) {
  if (node.IsNull()) return "";
  if (!node.IsMap()) return "labels must be a mapping NAME: [col, row] or NAME: [col, row, width, height]";
  for (const auto& entry : node) {
    if (!entry.first.IsScalar()) return "label names must be plain words";
    const std::string name = entry.first.Scalar();
    if (!OccupancyMap::validLabelName(name)) {
      return "label name '" + name + "' is not valid (a letter, then letters, digits, '_' or '-', at most 64)";
    }
    const YAML::Node& v = entry.second;
    CellBlock b;
    if (!v.IsSequence() || (v.size() != 2 && v.size() != 4)) {
      return "label '" + name + "' must be [col, row] or [col, row, width, height]";
    }
    int values[4] = {0, 0, 1, 1};
    for (size_t i = 0; i < v.size(); ++i) {
      if (!readInt(v[i], values[i])) return "label '" + name + "' has a value that is not a whole number";
    }
    b = CellBlock{values[0], values[1], values[2], values[3]};
    if (!map.setLabel(name, b)) {
      return "label '" + name + "' lies outside the " + std::to_string(map.width()) + "x" +
             std::to_string(map.height()) + " map (or has a size below 1)";
    }
  }
  return "";
}

std::string pgmBytes(const OccupancyMap& map) {
  char header[128];
  std::snprintf(header, sizeof header, "P5\n# CREATOR: nxtmap %.3f m/pix\n%d %d\n255\n", map.resolutionM(),
                map.width(), map.height());
  std::string out(header);
  out.reserve(out.size() + static_cast<size_t>(map.width()) * static_cast<size_t>(map.height()));
  for (int r = 0; r < map.height(); ++r) {
    for (int c = 0; c < map.width(); ++c) {
      int v = kPgmUnknown;
      switch (map.at(c, r)) {
        case Occupancy::Free: v = kPgmFree; break;
        case Occupancy::Occupied: v = kPgmOccupied; break;
        case Occupancy::Unknown: v = kPgmUnknown; break;
      }
      out.push_back(static_cast<char>(v));
    }
  }
  return out;
}

std::string yamlText(const OccupancyMap& map, const std::string& imageName) {
  std::ostringstream y;
  y << "image: " << imageName << "\n"
    << "mode: trinary\n"
    << "resolution: " << formatDouble(map.resolutionM()) << "\n"
    << "origin: [" << formatDouble(map.origin().x) << ", " << formatDouble(map.origin().y) << ", "
    << formatDouble(map.origin().yaw) << "]\n"
    << "negate: 0\n"
    << "occupied_thresh: 0.65\n"
    << "free_thresh: 0.196\n";
  if (!map.labels().empty()) {
    y << "labels:\n";
    for (const auto& [name, b] : map.labels()) {
      y << "  " << name << ": [" << b.col << ", " << b.row;
      if (b.width != 1 || b.height != 1) y << ", " << b.width << ", " << b.height;
      y << "]\n";
    }
  }
  return y.str();
}

}  // namespace

MapLoad loadMovingAiMap(const std::string& path) {
  const sim::WorldLoad w = sim::World::loadMovingAi(path);
  if (!w.world) return fail(w.error);
  return MapLoad{fromWorld(*w.world), {}};
}

MapLoad loadRosMap(const std::string& yamlPath) {
  std::string imageName;
  double resolution = 0.0;
  double occupiedThresh = 0.0;
  double freeThresh = 0.0;
  bool negate = false;
  MapOrigin origin;
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(yamlPath);
  } catch (const YAML::BadFile&) {
    return fail(yamlPath + ": cannot open file");
  } catch (const YAML::Exception& e) {
    return fail(yamlPath + ": " + e.what());
  }
  if (!doc.IsMap()) return fail(yamlPath + ": not a YAML mapping of map_server keys");
  for (const char* key : {"image", "resolution", "occupied_thresh", "free_thresh"}) {
    if (!doc[key]) return fail(yamlPath + ": missing key '" + key + "'");
  }
  if (!doc["image"].IsScalar() || doc["image"].Scalar().empty()) return fail(yamlPath + ": 'image' must name a file");
  imageName = doc["image"].Scalar();
  if (!readDouble(doc["resolution"], resolution) || !(resolution > 0.0)) {
    return fail(yamlPath + ": 'resolution' must be a number > 0");
  }
  if (!readDouble(doc["occupied_thresh"], occupiedThresh) || !readDouble(doc["free_thresh"], freeThresh)) {
    return fail(yamlPath + ": 'occupied_thresh' and 'free_thresh' must be numbers");
  }
  if (!(freeThresh >= 0.0 && freeThresh <= occupiedThresh && occupiedThresh <= 1.0)) {
    return fail(yamlPath + ": thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1");
  }
  if (doc["negate"] && (!doc["negate"].IsScalar() || !readFlag(doc["negate"], negate))) {
    return fail(yamlPath + ": 'negate' must be 0 or 1");
  }
  if (doc["origin"]) {
    const YAML::Node o = doc["origin"];
    if (!o.IsSequence() || o.size() != 3 || !readDouble(o[0], origin.x) || !readDouble(o[1], origin.y) ||
        !readDouble(o[2], origin.yaw)) {
      return fail(yamlPath + ": 'origin' must be [x, y, yaw] (three numbers)");
    }
  }
  if (doc["mode"]) {
    const std::string mode = doc["mode"].IsScalar() ? doc["mode"].Scalar() : "?";
    if (mode != "trinary") return fail(yamlPath + ": mode '" + mode + "' not supported (only trinary)");
  }

  fs::path imagePath(imageName);
  if (imagePath.is_relative()) imagePath = fs::path(yamlPath).parent_path() / imagePath;
  std::string error;
  const std::optional<sim::PgmImage> img = sim::readPgm(imagePath.string(), error);
  if (!img) return fail(yamlPath + ": " + error);
  if (img->width > OccupancyMap::kMaxSide || img->height > OccupancyMap::kMaxSide) {
    return fail(yamlPath + ": image larger than " + std::to_string(OccupancyMap::kMaxSide) + " pixels a side");
  }

  OccupancyMap map(img->width, img->height, Occupancy::Unknown, resolution, origin);
  for (int r = 0; r < img->height; ++r) {
    for (int c = 0; c < img->width; ++c) {
      const size_t i = static_cast<size_t>(r) * static_cast<size_t>(img->width) + static_cast<size_t>(c);
      const double shade = static_cast<double>(img->pixels[i]) / img->maxval;
      const double occ = negate ? shade : 1.0 - shade;
      Occupancy s = Occupancy::Unknown;
      if (occ > occupiedThresh) {
        s = Occupancy::Occupied;
      } else if (occ < freeThresh) {
        s = Occupancy::Free;
      }
      map.set(c, r, s);
    }
  }
  if (doc["labels"]) {
    const std::string labelError = readLabels(doc["labels"], map);
    if (!labelError.empty()) return fail(yamlPath + ": " + labelError);
  }
  return MapLoad{std::move(map), {}};
}

MapLoad loadMap(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".map") return loadMovingAiMap(path);
  if (ext == ".yaml" || ext == ".yml") return loadRosMap(path);
  return fail(path + ": unknown map format (expected .map, .yaml or .yml)");
}

OccupancyMap fromWorld(const sim::World& world) {
  OccupancyMap map(world.width(), world.height(), Occupancy::Free, world.resolutionM());
  for (int r = 0; r < world.height(); ++r) {
    for (int c = 0; c < world.width(); ++c) {
      if (world.blocked(c, r)) map.set(c, r, Occupancy::Occupied);
    }
  }
  return map;
}

std::string pgmNameFor(const std::string& yamlPath) { return fs::path(yamlPath).stem().string() + ".pgm"; }

bool saveRosMap(const OccupancyMap& map, const std::string& yamlPath, std::string& error) {
  const std::string ext = lowerExtension(yamlPath);
  if (ext != ".yaml" && ext != ".yml") {
    error = yamlPath + ": a saved map must be named *.yaml or *.yml";
    return false;
  }
  if (map.width() < 1 || map.height() < 1) {
    error = yamlPath + ": nothing to save (empty map)";
    return false;
  }
  const std::string imageName = pgmNameFor(yamlPath);
  const std::string pgmPath = (fs::path(yamlPath).parent_path() / imageName).string();
  // Both targets are checked (and their temporary files made) before either is written.
  fileio::AtomicFile pgm, yaml;
  if (!pgm.open(pgmPath, error) || !yaml.open(yamlPath, error)) return false;
  return pgm.write(pgmBytes(map), error) && yaml.write(yamlText(map, imageName), error) && pgm.commit(error) &&
         yaml.commit(error);
}

}  // namespace nxtmap::mapio
