#pragma once
#include <cstdint>

#include "common/grid/RoomGrid.hpp"

namespace nxtmap::fw {

// The final room map laid out for a reader outside the program (the brick emulator's end-to-end
// test reads it from RAM by symbol): little-endian, no padding, cells of the grid's window in
// row-major order from (minX, minY), 2 bits each (CellState) at bits 2*(i%4) of byte i/4.
struct MapExport {
  static constexpr uint32_t kMagic = 0x3150414D;  // "MAP1"
  uint32_t magic = 0;
  int16_t minX = 0, minY = 0, width = 0, height = 0;
  uint8_t cells[1024] = {};

  void fill(const RoomGrid& grid) {
    const Bounds w = grid.window();
    minX = w.minX;
    minY = w.minY;
    width = w.width();
    height = w.height();
    for (auto& b : cells) b = 0;
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const int i = y * width + x;
        if (i / 4 >= static_cast<int>(sizeof(cells))) return;
        const uint8_t s =
            static_cast<uint8_t>(grid.at(Cell{static_cast<int16_t>(minX + x), static_cast<int16_t>(minY + y)}));
        cells[i / 4] = static_cast<uint8_t>(cells[i / 4] | ((s & 3u) << (2 * (i % 4))));
      }
    }
    magic = kMagic;
  }
};
static_assert(sizeof(MapExport) == 4 + 8 + 1024, "no padding: read by address from outside");

}  // namespace nxtmap::fw
