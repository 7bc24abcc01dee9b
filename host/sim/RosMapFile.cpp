#include "host/sim/RosMapFile.hpp"

#include "host/sim/InputFile.hpp"
#include "host/sim/PgmImage.hpp"

#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace nxtmap::sim {

namespace {

// The keys of the YAML, read and checked (the image not yet read).
struct RosMapKeys {
  std::string image;
  double resolution = 0.0;
  double occupiedThresh = 0.0;
  double freeThresh = 0.0;
  bool negate = false;
  double origin[3] = {0.0, 0.0, 0.0};
};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool readFlag(const YAML::Node& node, bool& out) {
  if (!node.IsScalar()) return false;
  const std::string& s = node.Scalar();
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
  const std::string& s = node.Scalar();
  const auto res = std::from_chars(s.data(), s.data() + s.size(), out);
  return res.ec == std::errc() && res.ptr == s.data() + s.size();
}

// "" or why the resolution is refused.
std::string resolutionProblem(const YAML::Node& node, double& resolution) {
  const std::string range = "in " + number(kMinResolutionM) + " .. " + number(kMaxResolutionM) + " m per cell";
  if (!readDouble(node, resolution) || !(resolution > 0.0)) {
    return "'resolution' must be a number > 0, " + range + (node.IsScalar() ? ", not '" + node.Scalar() + "'" : "");
  }
  if (resolution < kMinResolutionM || resolution > kMaxResolutionM) {
    return "'resolution' " + number(resolution) + " is out of range: it must be " + range;
  }
  return "";
}

// "" or why the origin is refused.
std::string originProblem(const YAML::Node& o, double (&origin)[3]) {
  if (!o.IsSequence() || o.size() != 3 || !readDouble(o[0], origin[0]) || !readDouble(o[1], origin[1]) ||
      !readDouble(o[2], origin[2])) {
    return "'origin' must be [x, y, yaw] (three numbers)";
  }
  if (std::fabs(origin[0]) > kMaxOriginM || std::fabs(origin[1]) > kMaxOriginM ||
      std::fabs(origin[2]) > kMaxOriginYawRad) {
    return "'origin' [" + number(origin[0]) + ", " + number(origin[1]) + ", " + number(origin[2]) +
           "] is out of range: x and y must lie within +-" + number(kMaxOriginM) + " m, yaw within +-" +
           number(kMaxOriginYawRad) + " rad";
  }
  return "";
}

// Reads and checks every key but the labels; "" or the problem.
std::string readKeys(const YAML::Node& doc, RosMapKeys& k) {
  if (!doc.IsMap()) return "not a YAML mapping of map_server keys";
  for (const char* key : {"image", "resolution", "occupied_thresh", "free_thresh"}) {
    if (!doc[key]) return std::string("missing key '") + key + "'";
  }
  if (!doc["image"].IsScalar() || doc["image"].Scalar().empty()) return "'image' must name a file";
  k.image = doc["image"].Scalar();
  if (std::string why = resolutionProblem(doc["resolution"], k.resolution); !why.empty()) return why;
  if (!readDouble(doc["occupied_thresh"], k.occupiedThresh) || !readDouble(doc["free_thresh"], k.freeThresh)) {
    return "'occupied_thresh' and 'free_thresh' must be numbers";
  }
  if (!(k.freeThresh >= 0.0 && k.freeThresh <= k.occupiedThresh && k.occupiedThresh <= 1.0)) {
    return "thresholds must satisfy 0 <= free_thresh <= occupied_thresh <= 1";
  }
  if (doc["negate"] && !readFlag(doc["negate"], k.negate)) return "'negate' must be 0 or 1";
  if (doc["origin"]) {
    if (std::string why = originProblem(doc["origin"], k.origin); !why.empty()) return why;
  }
  if (doc["mode"]) {
    const std::string mode = doc["mode"].IsScalar() ? doc["mode"].Scalar() : "?";
    if (mode != "trinary") return "mode '" + mode + "' not supported (only trinary)";
  }
  return "";
}

// Reads `labels:` (shape and whole numbers only); "" or the problem.
std::string readLabels(const YAML::Node& node, std::vector<RosMapLabel>& labels) {
  if (node.IsNull()) return "";
  if (!node.IsMap()) return "labels must be a mapping NAME: [col, row] or NAME: [col, row, width, height]";
  for (const auto& entry : node) {
    if (!entry.first.IsScalar()) return "label names must be plain words";
    const std::string name = entry.first.Scalar();
    const YAML::Node& v = entry.second;
    if (!v.IsSequence() || (v.size() != 2 && v.size() != 4)) {
      return "label '" + name + "' must be [col, row] or [col, row, width, height]";
    }
    int values[4] = {0, 0, 1, 1};
    for (size_t i = 0; i < v.size(); ++i) {
      if (!readInt(v[i], values[i])) return "label '" + name + "' has a value that is not a whole number";
    }
    labels.push_back(RosMapLabel{name, values[0], values[1], values[2], values[3]});
  }
  return "";
}

RosCell classify(uint16_t pixel, int maxval, const RosMapKeys& k) {
  const double shade = static_cast<double>(pixel) / maxval;
  const double occ = k.negate ? shade : 1.0 - shade;
  if (occ > k.occupiedThresh) return RosCell::Occupied;
  if (occ < k.freeThresh) return RosCell::Free;
  return RosCell::Unknown;
}

}  // namespace

std::optional<RosMapFile> readRosMapFile(const std::string& yamlPath, std::string& error) {
  const std::optional<std::string> text = readInputFile(yamlPath, kMaxRosYamlBytes, "file", error);
  if (!text) return std::nullopt;
  auto fail = [&](const std::string& why) {
    error = yamlPath + ": " + why;
    return std::nullopt;
  };
  RosMapKeys keys;
  RosMapFile map;
  try {
    const YAML::Node doc = YAML::Load(*text);
    if (std::string why = readKeys(doc, keys); !why.empty()) return fail(why);
    if (doc["labels"]) {
      if (std::string why = readLabels(doc["labels"], map.labels); !why.empty()) return fail(why);
    }
  } catch (const YAML::Exception& e) {
    return fail(e.what());
  }

  std::filesystem::path imagePath(keys.image);
  if (imagePath.is_relative()) imagePath = std::filesystem::path(yamlPath).parent_path() / imagePath;
  std::string imageError;
  const std::optional<PgmImage> img = readPgm(imagePath.string(), imageError);
  if (!img) return fail(imageError);

  map.width = img->width;
  map.height = img->height;
  map.resolutionM = keys.resolution;
  map.originX = keys.origin[0];
  map.originY = keys.origin[1];
  map.originYaw = keys.origin[2];
  map.cells.reserve(img->pixels.size());
  for (const uint16_t pixel : img->pixels) map.cells.push_back(classify(pixel, img->maxval, keys));
  return map;
}

}  // namespace nxtmap::sim
