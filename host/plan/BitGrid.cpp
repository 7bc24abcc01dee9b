#include "host/plan/BitGrid.hpp"

namespace nxtmap::plan {

BitGrid::BitGrid(int paddedWidth, int paddedHeight, const std::vector<uint8_t>& cells)
    : rowWords_((paddedWidth + 63) / 64),
      colWords_((paddedHeight + 63) / 64),
      rows_(static_cast<std::size_t>(paddedHeight) * static_cast<std::size_t>(rowWords_), 0),
      cols_(static_cast<std::size_t>(paddedWidth) * static_cast<std::size_t>(colWords_), 0) {
  for (int y = 0; y < paddedHeight; ++y) {
    for (int x = 0; x < paddedWidth; ++x) {
      if (cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(paddedWidth) + static_cast<std::size_t>(x)] == 0)
        continue;
      rows_[static_cast<std::size_t>(y) * static_cast<std::size_t>(rowWords_) + static_cast<std::size_t>(x >> 6)] |=
          uint64_t{1} << (x & 63);
      cols_[static_cast<std::size_t>(x) * static_cast<std::size_t>(colWords_) + static_cast<std::size_t>(y >> 6)] |=
          uint64_t{1} << (y & 63);
    }
  }
}

}  // namespace nxtmap::plan
