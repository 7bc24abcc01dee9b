// MapImage: a PNG picture of a run's belief (free white, unknown grey, occupied black, robot red),
// optionally with the true world overlaid: missed obstacles light red, obstacles mapped free orange, walls mapped on
// open floor blue.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "common/grid/CellState.hpp"
#include "host/sim/Heading.hpp"

namespace nxtmap::mapping {
class MappingRun;
}
namespace nxtmap::sim {
class World;
}

namespace nxtmap::report {

// The largest side of a map picture, pixels (192 MiB of RGB at most; the world's 4096 cells at 1 px fit).
constexpr int kMaxPictureSide = 8192;

// Pixels per cell for a world `worldSide` cells on its longer side: as asked (1..64), fewer for a large world so
// the picture keeps within kMaxPictureSide pixels a side (a 4096-cell world at 8 px would take 3.2 GB).
int pictureCellPx(int worldSide, int askedPx);

struct MapImageOptions {
  int cellPx = 8;            // pixels per cell side (1..64; fewer when the world is too large for it)
  bool overlayTruth = true;  // mark missed obstacles and both kinds of wrong cell against the world
  bool gridLines = true;     // thin lines between cells (when cellPx >= 6)
};

// An 8-bit RGB picture, row-major, 3 bytes per pixel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  void fill(int x0, int y0, int w, int h, uint8_t r, uint8_t g, uint8_t b);
  void pixel(int x, int y, uint8_t& r, uint8_t& g, uint8_t& b) const;
};

// A belief to draw: the state of every cell of `world` (col right, row down), and the robot's believed cell and
// heading on it (a cell outside the world: no robot drawn).
struct BeliefPicture {
  const sim::World* world = nullptr;
  std::function<CellState(int col, int row)> belief;
  int robotCol = -1, robotRow = -1;
  sim::Heading heading = sim::Heading::N;
};

// The picture of a belief over its world's extent.
RgbImage renderBeliefImage(const BeliefPicture& picture, const MapImageOptions& options = {});
// The picture of the run's belief over its world's extent.
RgbImage renderMapImage(const mapping::MappingRun& run, const MapImageOptions& options = {});

// Writes an RGB PNG whole or not at all (fileio::AtomicFile: a temporary file beside `path`, renamed over it);
// false with `error` set (the path and the reason) when it cannot be written, `path` then untouched.
bool writePng(const std::string& path, const RgbImage& image, std::string& error);

// renderMapImage + writePng.
bool writeMapPng(const std::string& path, const mapping::MappingRun& run, const MapImageOptions& options,
                 std::string& error);

}  // namespace nxtmap::report
