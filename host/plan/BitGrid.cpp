#include "host/plan/BitGrid.hpp"

namespace nxtmap::plan {

BitGrid::BitGrid(int paddedWidth, int paddedHeight, const std::vector<uint8_t>& cells)
    : rowWords_((paddedWidth + 63) / 64),
      colWords_((paddedHeight + 63) / 64),
      rows_(static_cast<std::size_t>(paddedHeight) * static_cast<std::size_t>(rowWords_), 0),
      cols_(static_cast<std::size_t>(paddedWidth) * static_cast<std::size_t>(colWords_), 0) {
  for (int y = 0; y < paddedHeight; ++y) {
    for (int x = 0; x < paddedWidth; ++x) {
      if (cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(paddedWidth) + static_cast<std::size_t>(x)] == 0) continue;
      rows_[static_cast<std::size_t>(y) * static_cast<std::size_t>(rowWords_) + static_cast<std::size_t>(x >> 6)] |= uint64_t{1} << (x & 63);
      cols_[static_cast<std::size_t>(x) * static_cast<std::size_t>(colWords_) + static_cast<std::size_t>(y >> 6)] |= uint64_t{1} << (y & 63);
    }
  }
}

int BitGrid::scanUp(const uint64_t* before, const uint64_t* line, const uint64_t* after, int words, int from) {
  if (from < 0) from = 0;
  int k = from >> 6;
  uint64_t mask = ~uint64_t{0} << (from & 63);
  for (; k < words; ++k, mask = ~uint64_t{0}) {
    const uint64_t b = before[k], a = after[k];
    // Bit p of bLow / aLow: the side line at p - 1.
    const uint64_t bLow = (b << 1) | (k > 0 ? before[k - 1] >> 63 : 0);
    const uint64_t aLow = (a << 1) | (k > 0 ? after[k - 1] >> 63 : 0);
    const uint64_t stop = (~line[k] | (b & ~bLow) | (a & ~aLow)) & mask;
    if (stop != 0) return k * 64 + __builtin_ctzll(stop);
  }
  return words * 64;
}

int BitGrid::scanDown(const uint64_t* before, const uint64_t* line, const uint64_t* after, int words, int from) {
  if (from >= words * 64) from = words * 64 - 1;
  int k = from >> 6;
  uint64_t mask = ~uint64_t{0} >> (63 - (from & 63));
  for (; k >= 0; --k, mask = ~uint64_t{0}) {
    const uint64_t b = before[k], a = after[k];
    // Bit p of bHigh / aHigh: the side line at p + 1.
    const uint64_t bHigh = (b >> 1) | (k + 1 < words ? before[k + 1] << 63 : 0);
    const uint64_t aHigh = (a >> 1) | (k + 1 < words ? after[k + 1] << 63 : 0);
    const uint64_t stop = (~line[k] | (b & ~bHigh) | (a & ~aHigh)) & mask;
    if (stop != 0) return k * 64 + 63 - __builtin_clzll(stop);
  }
  return -1;
}

}  // namespace nxtmap::plan
