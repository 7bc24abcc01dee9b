// ExplorerBuffer: the memory of one ExplorerStack on the PC, of a capacity chosen at run time.
// By default it is the brick's own (BrickExplorerStorage: 64 x 64 cells, a 1024-state planner
// queue), so a simulated run meets the brick's limits; a larger grid is an explicit choice.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/explore/ExplorerStorage.hpp"

namespace nxtmap::mapping {

// A room grid's capacity: cells per side (a power of two, 16..128) and the planner's queue.
struct GridCapacity {
  int16_t cells = BrickExplorerStorage::kWidth();
  uint16_t queue = 1024;  // travel-search states held at once (the brick's)

  static GridCapacity brick() { return GridCapacity{}; }
  // 16, 32, 64 (the brick's), 128 cells per side; empty for anything else. Larger than the
  // brick's: the queue grows with the grid (8192 at 128, as the host runs had before).
  static std::optional<GridCapacity> ofCells(int cells);
  bool isBrick() const { return cells == brick().cells && queue == brick().queue; }
  std::string describe() const;  // e.g. "64 x 64 cells (the brick's)"
};

class ExplorerBuffer {
 public:
  explicit ExplorerBuffer(GridCapacity capacity = GridCapacity::brick());
  ExplorerBuffer(const ExplorerBuffer&) = delete;
  ExplorerBuffer& operator=(const ExplorerBuffer&) = delete;

  // Views of the buffer for an ExplorerStack; valid while the buffer lives.
  ExplorerMemory memory();
  const GridCapacity& capacity() const { return capacity_; }

 private:
  GridCapacity capacity_;
  std::vector<uint8_t> grid_, evidence_, reads_, diagonals_, labels_, reported_;
  std::vector<uint16_t> queue_;
};

}  // namespace nxtmap::mapping
