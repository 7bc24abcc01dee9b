#include "host/sim/World.hpp"

#include "host/sim/MovingAiFile.hpp"
#include "host/sim/RosMapFile.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace nxtmap::sim {

namespace {

std::string stemOf(const std::string& path) { return std::filesystem::path(path).stem().string(); }

WorldLoad fail(std::string message) { return WorldLoad{std::nullopt, std::move(message)}; }

}  // namespace

World::World(int width, int height, double resolutionM, std::string name, std::vector<uint8_t> cells)
    : width_(width), height_(height), resolutionM_(resolutionM), name_(std::move(name)), cells_(std::move(cells)) {}

std::string World::resolutionProblem(double resolutionM) {
  const double cm = resolutionM * 100.0;
  // 1e-6 cm: the decimal metres of a file (0.05) are not exact in binary, whole centimetres are near enough.
  if (std::isfinite(cm) && std::fabs(cm - std::round(cm)) <= 1e-6 && std::round(cm) >= kMinCellCm &&
      std::round(cm) <= kMaxCellCm) {
    return "";
  }
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "resolution %g m is not one the simulator can use: its cells must be a whole number of "
                "centimetres, %d .. %d cm (0.%02d .. %d.%02d m)",
                resolutionM, kMinCellCm, kMaxCellCm, kMinCellCm, kMaxCellCm / 100, kMaxCellCm % 100);
  return buf;
}

World World::fromRows(const std::vector<std::string>& rows, double resolutionM) {
  size_t w = 0;
  for (const auto& r : rows) w = std::max(w, r.size());
  std::vector<uint8_t> cells(w * rows.size(), 0);
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t c = 0; c < rows[r].size(); ++c) {
      const char ch = rows[r][c];
      cells[r * w + c] = (ch == '.' || ch == ' ') ? 0 : 1;
    }
  }
  return World(static_cast<int>(w), static_cast<int>(rows.size()), resolutionM, "rows", std::move(cells));
}

World World::fromCells(int width, int height, double resolutionM, std::string name, std::vector<uint8_t> cells) {
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide ||
      cells.size() != static_cast<size_t>(width) * static_cast<size_t>(height)) {
    throw std::invalid_argument("World::fromCells: " + std::to_string(width) + " x " + std::to_string(height) +
                                " cells do not match " + std::to_string(cells.size()) + " values");
  }
  for (uint8_t& c : cells) c = static_cast<uint8_t>(c != 0 ? 1 : 0);
  return World(width, height, resolutionM, std::move(name), std::move(cells));
}

WorldLoad World::load(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".map") return loadMovingAi(path);
  if (ext == ".yaml" || ext == ".yml") return loadRosYaml(path);
  return fail(path + ": unknown world format (expected .map, .yaml or .yml)");
}

WorldLoad World::loadMovingAi(const std::string& path, double resolutionM) {
  if (const std::string why = resolutionProblem(resolutionM); !why.empty()) return fail(path + ": " + why);
  std::string error;
  std::optional<MovingAiGrid> grid = readMovingAiFile(path, error);
  if (!grid) return fail(error);
  return WorldLoad{World(grid->width, grid->height, resolutionM, stemOf(path), std::move(grid->blocked)), {}};
}

WorldLoad World::loadRosYaml(const std::string& yamlPath) {
  std::string error;
  const std::optional<RosMapFile> file = readRosMapFile(yamlPath, error);
  if (!file) return fail(error);
  if (const std::string why = resolutionProblem(file->resolutionM); !why.empty()) return fail(yamlPath + ": " + why);
  // Free cells are free; occupied and unknown ones are blocked. Image row 0 is our row 0 (rows grow down).
  std::vector<uint8_t> cells(file->cells.size(), 1);
  for (size_t i = 0; i < file->cells.size(); ++i) {
    if (file->cells[i] == RosCell::Free) cells[i] = 0;
  }
  return WorldLoad{World(file->width, file->height, file->resolutionM, stemOf(yamlPath), std::move(cells)), {}};
}

}  // namespace nxtmap::sim
