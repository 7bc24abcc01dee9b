// BitGrid: the passable cells of a padded grid as bitsets, one per row and one per column (a transposed
// copy), so that a straight jump tests 64 cells per step (block-based jump point search, after Harabor &
// Grastien, "Improving Jump Point Search", ICAPS 2014).
//
// Coordinates are padded: x = map column + 1 in 0..paddedWidth-1, y = map row + 1 in 0..paddedHeight-1.
// Row y holds bit x (word x / 64, bit x % 64) = cell (x, y) passable; column x holds bit y likewise. Bits
// past the padded width (height) are 0, i.e. blocked, as is the padding.
// Memory: 2 bits per cell, rounded up to whole 64-bit words per row and per column.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace nxtmap::plan {

class BitGrid {
 public:
  BitGrid() = default;
  // cells: paddedWidth * paddedHeight bytes, row by row, non-zero = passable.
  BitGrid(int paddedWidth, int paddedHeight, const std::vector<uint8_t>& cells);

  int rowWords() const { return rowWords_; }     // words per row
  int columnWords() const { return colWords_; }  // words per column
  const uint64_t* row(int y) const { return &rows_[static_cast<std::size_t>(y) * static_cast<std::size_t>(rowWords_)]; }
  const uint64_t* column(int x) const {
    return &cols_[static_cast<std::size_t>(x) * static_cast<std::size_t>(colWords_)];
  }
  // Cell (x, y) passable; x, y must be padded coordinates.
  bool open(int x, int y) const { return test(row(y), x); }

  static bool test(const uint64_t* line, int p) { return (line[p >> 6] >> (p & 63)) & 1u; }

  // Scans `line` (of `words` words) upwards from position `from`: the first p >= from where line is blocked
  // or where a side line (`before` or `after`) is open at p but blocked at p - 1 (a forced neighbour of a
  // move in the + direction). words * 64 when there is none.
  static inline int scanUp(const uint64_t* before, const uint64_t* line, const uint64_t* after, int words, int from);
  // The mirror: the last p <= from where line is blocked or a side line is open at p but blocked at p + 1.
  // -1 when there is none.
  static inline int scanDown(const uint64_t* before, const uint64_t* line, const uint64_t* after, int words, int from);

 private:
  int rowWords_ = 0;
  int colWords_ = 0;
  std::vector<uint64_t> rows_;  // paddedHeight rows of rowWords_
  std::vector<uint64_t> cols_;  // paddedWidth columns of colWords_
};

inline int BitGrid::scanUp(const uint64_t* before, const uint64_t* line, const uint64_t* after, int words, int from) {
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

inline int BitGrid::scanDown(const uint64_t* before, const uint64_t* line, const uint64_t* after, int words, int from) {
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
