#pragma once
// Test helpers: a map from ASCII rows ('.' free, '#' occupied, '?' or ' ' unknown).
// The first row is the top (highest y); `origin` names the cell that becomes (0,0).
#include <string>
#include <vector>

#include "common/explore/ExplorerStorage.hpp"
#include "common/grid/MapLayers.hpp"

namespace nxtmap::test {

struct GridFixture {
  MapStorage<32, 32> storage{};
  MapLayers map{storage.view(), 32, 32};

  // Cell (col, row) of the picture (row 0 = top line) becomes (col - ox, (rows-1-row) - oy).
  void draw(const std::vector<std::string>& rows, int ox = 0, int oy = 0) {
    const int h = static_cast<int>(rows.size());
    for (int r = 0; r < h; ++r) {
      for (int c = 0; c < static_cast<int>(rows[r].size()); ++c) {
        const Cell cell{static_cast<int16_t>(c - ox), static_cast<int16_t>(h - 1 - r - oy)};
        const char ch = rows[r][c];
        if (ch == '.') (void)map.observeFree(cell);
        if (ch == '#') (void)map.observeOccupied(cell);
      }
    }
  }
  RoomGrid& grid() { return map.grid(); }
};

// The grid's window as ASCII rows, top row first.
inline std::vector<std::string> picture(const RoomGrid& g) {
  std::vector<std::string> out;
  const Bounds w = g.window();
  for (int16_t y = w.maxY; y >= w.minY; --y) {
    std::string line;
    for (int16_t x = w.minX; x <= w.maxX; ++x) {
      const CellState s = g.at(Cell{x, y});
      line += s == CellState::Free ? '.' : s == CellState::Occupied ? '#' : '?';
    }
    out.push_back(line);
  }
  return out;
}

}  // namespace nxtmap::test
