// JumpTable: jump distances precomputed for every cell and each of the 8 directions (JPS+, Harabor &
// Grastien 2012), for the no-corner-cutting moves of Traversability, so that a jump costs one lookup.
//
// at(i, d) for padded index i and direction d (kDirs order): > 0 = a jump point that many steps away
// (straight: a cell with a forced neighbour; diagonal: a cell from which a straight jump along one of the
// two components reaches a jump point); <= 0 = -k: k free steps, then the way is blocked. The goal is not in
// the table: the search checks it at query time.
// Memory: 16 bytes per cell (4 MB for 512 x 512).
#pragma once

#include <cstdint>
#include <vector>

#include "host/plan/Traversability.hpp"

namespace nxtmap::plan {

class JumpTable {
 public:
  // (dc, dr) per direction: 0..3 straight (E, W, S, N), 4..7 diagonal (SE, NE, SW, NW).
  static constexpr int kDirs[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
  static int direction(int dc, int dr);  // index in kDirs

  explicit JumpTable(const Traversability& grid);
  uint64_t gridId() const { return gridId_; }
  int16_t at(uint32_t i, int d) const { return table_[static_cast<size_t>(i) * 8 + static_cast<size_t>(d)]; }

 private:
  uint64_t gridId_;
  std::vector<int16_t> table_;  // padded index * 8 + direction
};

}  // namespace nxtmap::plan
