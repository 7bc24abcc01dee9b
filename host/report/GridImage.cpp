#include "host/report/GridImage.hpp"

#include <algorithm>
#include <cstdint>

namespace nxtmap::report {
namespace {
constexpr uint8_t kFreeGrey = 255, kUnknownGrey = 160, kOccupiedGrey = 0;
constexpr uint8_t kRobotR = 220, kRobotG = 30, kRobotB = 30;

uint8_t greyOf(CellState s) {
  return s == CellState::Free ? kFreeGrey : (s == CellState::Occupied ? kOccupiedGrey : kUnknownGrey);
}
}  // namespace

RgbImage renderGridImage(int width, int height, const std::function<CellState(int, int)>& cell,
                         const std::optional<RobotMark>& robot, const GridImageOptions& options) {
  const int px = std::clamp(options.cellPx, 1, 64);
  RgbImage img;
  img.width = std::max(0, width) * px;
  img.height = std::max(0, height) * px;
  img.rgb.assign(static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 3, 0);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const uint8_t g = greyOf(cell(col, row));
      img.fill(col * px, row * px, px, px, g, g, g);
    }
  }
  if (robot && robot->col >= 0 && robot->row >= 0 && robot->col < width && robot->row < height)
    img.fill(robot->col * px + 1, robot->row * px + 1, px - 2, px - 2, kRobotR, kRobotG, kRobotB);
  return img;
}

bool writeGridPng(const std::string& path, int width, int height, const std::function<CellState(int, int)>& cell,
                  const std::optional<RobotMark>& robot, std::string& error, const GridImageOptions& options) {
  return writePng(path, renderGridImage(width, height, cell, robot, options), error);
}

}  // namespace nxtmap::report
