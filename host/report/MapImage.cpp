#include "host/report/MapImage.hpp"

#include <algorithm>

#include "host/fileio/PngFile.hpp"
#include "host/mapping/MappingRun.hpp"

namespace nxtmap::report {
namespace {
struct Rgb {
  uint8_t r, g, b;
};
constexpr Rgb kFree{255, 255, 255};
constexpr Rgb kUnknown{160, 160, 160};
constexpr Rgb kOccupied{0, 0, 0};
constexpr Rgb kRobot{220, 0, 0};
constexpr Rgb kMissed{255, 170, 170};  // obstacle in the world, still unknown in the map
constexpr Rgb kWrong{255, 140, 0};     // free in the map where the world has an obstacle
constexpr Rgb kFalseWall{40, 90, 255};  // occupied in the map where the world is open floor
constexpr Rgb kGrid{215, 215, 215};
}  // namespace

void RgbImage::fill(int x0, int y0, int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  const int x1 = std::min(width, x0 + w), y1 = std::min(height, y0 + h);
  for (int y = std::max(0, y0); y < y1; ++y) {
    for (int x = std::max(0, x0); x < x1; ++x) {
      uint8_t* p = &rgb[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3];
      p[0] = r;
      p[1] = g;
      p[2] = b;
    }
  }
}

void RgbImage::pixel(int x, int y, uint8_t& r, uint8_t& g, uint8_t& b) const {
  const uint8_t* p = &rgb[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3];
  r = p[0];
  g = p[1];
  b = p[2];
}

int pictureCellPx(int worldSide, int askedPx) {
  return std::clamp(std::min(askedPx, kMaxPictureSide / std::max(worldSide, 1)), 1, 64);
}

RgbImage renderBeliefImage(const BeliefPicture& picture, const MapImageOptions& options) {
  const sim::World& world = *picture.world;
  const int px = pictureCellPx(std::max(world.width(), world.height()), options.cellPx);
  RgbImage img;
  img.width = world.width() * px;
  img.height = world.height() * px;
  img.rgb.assign(static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 3, 255);
  const bool lines = options.gridLines && px >= 6;
  for (int row = 0; row < world.height(); ++row) {
    for (int col = 0; col < world.width(); ++col) {
      const CellState b = picture.belief(col, row);
      const bool blocked = world.blocked(col, row);
      Rgb c = b == CellState::Free ? kFree : b == CellState::Occupied ? kOccupied : kUnknown;
      if (options.overlayTruth) {
        if (b == CellState::Unknown && blocked) c = kMissed;
        if (b == CellState::Free && blocked) c = kWrong;
        if (b == CellState::Occupied && !blocked) c = kFalseWall;
      }
      const int x = col * px, y = row * px;
      if (lines) {
        img.fill(x, y, px, px, kGrid.r, kGrid.g, kGrid.b);
        img.fill(x + 1, y + 1, px - 1, px - 1, c.r, c.g, c.b);
      } else {
        img.fill(x, y, px, px, c.r, c.g, c.b);
      }
    }
  }
  // The robot: a red square in its believed cell with a notch towards its heading.
  const int rc = picture.robotCol, rr = picture.robotRow;
  if (world.inside(rc, rr)) {
    const int inset = std::max(0, px / 5);
    const int x = rc * px, y = rr * px, s = px - 2 * inset;
    img.fill(x + inset, y + inset, s, s, kRobot.r, kRobot.g, kRobot.b);
    if (px >= 6) {
      const int n = std::max(1, px / 4), mid = px / 2 - n / 2;
      int nx = x + mid, ny = y + mid;
      switch (picture.heading) {
        case sim::Heading::N: ny = y + inset; break;
        case sim::Heading::E: nx = x + px - inset - n; break;
        case sim::Heading::S: ny = y + px - inset - n; break;
        case sim::Heading::W: nx = x + inset; break;
      }
      img.fill(nx, ny, n, n, 255, 255, 0);
    }
  }
  return img;
}

RgbImage renderMapImage(const mapping::MappingRun& run, const MapImageOptions& options) {
  BeliefPicture p;
  p.world = &run.world();
  p.belief = [&run](int col, int row) { return run.belief(col, row); };
  run.believedCell(p.robotCol, p.robotRow);
  p.heading = run.believedHeading();
  return renderBeliefImage(p, options);
}

bool writePng(const std::string& path, const RgbImage& image, std::string& error) {
  return fileio::writePngFile(path, image.width, image.height, 3, image.rgb.data(), error);
}

bool writeMapPng(const std::string& path, const mapping::MappingRun& run, const MapImageOptions& options,
                 std::string& error) {
  return writePng(path, renderMapImage(run, options), error);
}

}  // namespace nxtmap::report
