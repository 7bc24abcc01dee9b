#include "host/mapping/ExplorerBuffer.hpp"

namespace nxtmap::mapping {

std::optional<GridCapacity> GridCapacity::ofCells(int cells) {
  if (cells == 16 || cells == 32)
    return GridCapacity{static_cast<int16_t>(cells), static_cast<uint16_t>(cells * cells / 4)};
  if (cells == 64) return brick();
  if (cells == 128) return GridCapacity{128, 8192};
  return std::nullopt;
}

std::string GridCapacity::describe() const {
  const std::string side = std::to_string(cells);
  return side + " x " + side + " cells" + (isBrick() ? " (the brick's)" : "");
}

ExplorerBuffer::ExplorerBuffer(GridCapacity capacity)
    : capacity_(capacity),
      grid_(packedBytes(capacity.cells, capacity.cells, 2)),
      evidence_(packedBytes(capacity.cells, capacity.cells, 4)),
      reads_(packedBytes(capacity.cells, capacity.cells, 4)),
      diagonals_(packedBytes(capacity.cells, capacity.cells, 2)),
      labels_(packedBytes(static_cast<int16_t>(2 * capacity.cells), capacity.cells, 2)),
      reported_(packedBytes(capacity.cells, capacity.cells, 1)),
      queue_(capacity.queue) {}

ExplorerMemory ExplorerBuffer::memory() {
  return ExplorerMemory{MapLayers::Storage{grid_.data(), evidence_.data(), reads_.data(), diagonals_.data()},
                        TravelPlanner::Storage{labels_.data(), reported_.data(), queue_.data(), capacity_.queue},
                        capacity_.cells, capacity_.cells};
}

}  // namespace nxtmap::mapping
