// CellBox: an inclusive rectangle of cells in int (wider than a Cell's int16_t, so boxes of any
// room or house and their sizes compute without overflow). Never empty: minX <= maxX, minY <= maxY.
#pragma once

#include <algorithm>

#include "common/grid/Cell.hpp"

namespace nxtmap::network {

struct CellBox {
  int minX = 0, minY = 0, maxX = 0, maxY = 0;

  int width() const { return maxX - minX + 1; }
  int height() const { return maxY - minY + 1; }
  bool contains(Cell c) const { return c.x >= minX && c.x <= maxX && c.y >= minY && c.y <= maxY; }
  // The smallest box holding both.
  CellBox united(const CellBox& o) const {
    return CellBox{std::min(minX, o.minX), std::min(minY, o.minY), std::max(maxX, o.maxX), std::max(maxY, o.maxY)};
  }
  // The box with `cells` more on every side.
  CellBox grown(int cells) const { return CellBox{minX - cells, minY - cells, maxX + cells, maxY + cells}; }
};

}  // namespace nxtmap::network
