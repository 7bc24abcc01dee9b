#pragma once
#include <cstddef>

#include "common/explore/TravelPlanner.hpp"
#include "common/grid/MapLayers.hpp"

namespace nxtmap {

// The memory an explorer works in, as views: a map and a planner of width x height cells.
struct ExplorerMemory {
  MapLayers::Storage map;
  TravelPlanner::Storage travel;
  int16_t width;
  int16_t height;
};

// All the memory an explorer needs for a room of up to W x H cells, in one caller-owned block
// (a static on the brick, a member or local on the PC). No heap anywhere.
template <int W, int H, int QUEUE = (W * H) / 2>
struct ExplorerStorage {
  MapStorage<W, H> map;
  TravelStorage<W, H, QUEUE> travel;
  static constexpr int16_t kWidth() { return W; }
  static constexpr int16_t kHeight() { return H; }
  ExplorerMemory memory() { return ExplorerMemory{map.view(), travel.view(), W, H}; }
  static constexpr size_t kBytes = sizeof(MapStorage<W, H>) + sizeof(TravelStorage<W, H, QUEUE>);
};

// The brick's room grid: 64 x 64 cells (12.8 m at 20 cm cells).
using BrickExplorerStorage = ExplorerStorage<64, 64, 1024>;
// Half of the brick RAM budget (24 KiB with stacks): grid 1 KiB, evidence 2, read memory 2,
// diagonals 1, planner 4.5.
static_assert(BrickExplorerStorage::kBytes <= 12 * 1024, "explorer memory on the brick: <= 12 KiB");

}  // namespace nxtmap
