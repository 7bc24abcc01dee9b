#include "host/worlds/SiteFiles.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "host/house/HouseExpoPlan.hpp"
#include "host/sim/InputFile.hpp"
#include "host/sim/RosMapFile.hpp"
#include "host/sim/WorldFile.hpp"

namespace nxtmap::worlds {
namespace {

SiteLoad fail(std::string error) { return SiteLoad{std::nullopt, std::move(error)}; }
SiteLoad ok(sim::Site site) { return SiteLoad{std::move(site), {}}; }

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// An nxtmap world file names itself (`nxtmap_world: 1`); anything else goes to the ROS reader, whose
// messages then say what is wrong with it.
bool isWorldFile(const std::string& path) {
  std::string error;
  const std::optional<std::string> text = sim::readInputFile(path, sim::kMaxWorldFileBytes, "file", error);
  return text && sim::looksLikeWorldFile(*text);
}

SiteLoad rosSite(const std::string& path) {
  std::string error;
  std::optional<sim::RosMapFile> file = sim::readRosMapFile(path, error);
  if (!file) return fail(error);
  std::vector<uint8_t> cells(file->cells.size(), 1);
  for (size_t i = 0; i < file->cells.size(); ++i) {
    if (file->cells[i] == sim::RosCell::Free) cells[i] = 0;
  }
  return ok(sim::siteFromRaster(sim::World::fromCells(file->width, file->height, file->resolutionM,
                                                      std::filesystem::path(path).stem().string(), std::move(cells))));
}

SiteLoad worldFileSite(const std::string& path) {
  sim::WorldFileLoad load = sim::readWorldFile(path);
  if (!load.world) return fail(load.error);
  sim::Site site;
  site.name = load.world->name;
  site.scene = load.world->scene;
  if (load.world->hasStart) site.start = sim::StartPose{load.world->startCm, load.world->startHeadingDeg};
  return ok(std::move(site));
}

SiteLoad houseExpoSite(const std::string& path) {
  house::HousePlanLoad load = house::loadHouseExpo(path);
  if (!load.plan) return fail(load.error);
  int col = 0, row = 0;
  const bool hasStart = house::defaultStart(*load.plan, col, row);
  sim::Site site;
  site.name = std::filesystem::path(path).stem().string();
  site.scene = load.plan->scene;  // the outline exactly as given; the raster only for its cells and start
  site.raster = std::move(load.plan->world);
  if (hasStart) site.start = site.rasterStart(col, row, 0.0);
  return ok(std::move(site));
}

}  // namespace

SiteLoad loadSite(const std::string& path, int cellCm) {
  const std::string ext = lowerExtension(path);
  if (ext == ".map") {
    sim::WorldLoad w = sim::World::loadMovingAi(path, cellCm / 100.0);
    if (!w.world) return fail(w.error);
    return ok(sim::siteFromRaster(std::move(*w.world)));
  }
  if (ext == ".yaml" || ext == ".yml") return isWorldFile(path) ? worldFileSite(path) : rosSite(path);
  if (ext == ".json") return houseExpoSite(path);
  return fail(path + ": unknown world format (expected .map, .yaml, .yml or .json)");
}

}  // namespace nxtmap::worlds
