#include "host/mapio/MapFiles.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

#include "host/fileio/AtomicFile.hpp"
#include "host/sim/MovingAiFile.hpp"
#include "host/sim/RosMapFile.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::mapio {
namespace {

namespace fs = std::filesystem;

MapLoad fail(std::string message) { return MapLoad{std::nullopt, std::move(message)}; }

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Shortest text that reads back as the same double.
std::string formatDouble(double v) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

// Adds the file's labels to the map; returns an error text or "".
std::string addLabels(const std::vector<sim::RosMapLabel>& labels, OccupancyMap& map) {
  for (const sim::RosMapLabel& l : labels) {
    if (!OccupancyMap::validLabelName(l.name)) {
      return "label name '" + l.name + "' is not valid (a letter, then letters, digits, '_' or '-', at most 64)";
    }
    if (!map.setLabel(l.name, CellBlock{l.col, l.row, l.width, l.height})) {
      return "label '" + l.name + "' lies outside the " + std::to_string(map.width()) + "x" +
             std::to_string(map.height()) + " map (or has a size below 1)";
    }
  }
  return "";
}

Occupancy occupancyOf(sim::RosCell cell) {
  switch (cell) {
    case sim::RosCell::Free: return Occupancy::Free;
    case sim::RosCell::Occupied: return Occupancy::Occupied;
    case sim::RosCell::Unknown: return Occupancy::Unknown;
  }
  return Occupancy::Unknown;
}

std::string pgmBytes(const OccupancyMap& map) {
  char header[128];
  std::snprintf(header, sizeof header, "P5\n# CREATOR: nxtmap %.3f m/pix\n%d %d\n255\n", map.resolutionM(), map.width(),
                map.height());
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
  std::string error;
  const std::optional<sim::MovingAiGrid> grid = sim::readMovingAiFile(path, error);
  if (!grid) return fail(error);
  OccupancyMap map(grid->width, grid->height, Occupancy::Free, sim::kMovingAiResolutionM);
  for (int r = 0; r < grid->height; ++r) {
    for (int c = 0; c < grid->width; ++c) {
      const size_t i = static_cast<size_t>(r) * static_cast<size_t>(grid->width) + static_cast<size_t>(c);
      if (grid->blocked[i] != 0) map.set(c, r, Occupancy::Occupied);
    }
  }
  return MapLoad{std::move(map), {}};
}

MapLoad loadRosMap(const std::string& yamlPath) {
  std::string error;
  const std::optional<sim::RosMapFile> file = sim::readRosMapFile(yamlPath, error);
  if (!file) return fail(error);
  const MapOrigin origin{file->originX, file->originY, file->originYaw};
  OccupancyMap map(file->width, file->height, Occupancy::Unknown, file->resolutionM, origin);
  for (int r = 0; r < file->height; ++r) {
    for (int c = 0; c < file->width; ++c) {
      const size_t i = static_cast<size_t>(r) * static_cast<size_t>(file->width) + static_cast<size_t>(c);
      map.set(c, r, occupancyOf(file->cells[i]));
    }
  }
  const std::string labelError = addLabels(file->labels, map);
  if (!labelError.empty()) return fail(yamlPath + ": " + labelError);
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
