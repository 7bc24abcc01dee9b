#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/RoomGrid.hpp"
#include "firmware/app/Font3x5.hpp"

namespace nxtmap::fw {

// Draws into the LCD frame (8 pages x 100 columns, bit n of [page][x] = row 8*page + n, row 0 on
// top). Layout: the room map on the left 64 x 64 pixels (one pixel per cell, north up: occupied
// dark, free light, unknown as a sparse dot pattern, the robot as a blinking pixel plus one pixel
// towards its heading); status text in the 34 columns on the right.
class Screen {
 public:
  static constexpr int kWidth = 100, kHeight = 64, kMapSize = 64, kTextX = 67;
  using Frame = uint8_t[8][kWidth];

  explicit Screen(Frame& frame) : f_(frame) {}

  void clear() {
    for (auto& page : f_)
      for (auto& b : page) b = 0;
  }
  void pixel(int x, int y, bool dark) {
    if (x < 0 || x >= kWidth || y < 0 || y >= kHeight) return;
    const uint8_t bit = static_cast<uint8_t>(1u << (y & 7));
    if (dark)
      f_[y >> 3][x] = static_cast<uint8_t>(f_[y >> 3][x] | bit);
    else
      f_[y >> 3][x] = static_cast<uint8_t>(f_[y >> 3][x] & ~bit);
  }
  bool pixelAt(int x, int y) const { return (f_[y >> 3][x] >> (y & 7)) & 1u; }

  // Text at (x, y) = top-left, 4 pixels per character; returns the x after the last character.
  int text(int x, int y, const char* s) {
    for (; *s != 0; ++s, x += Font3x5::kAdvance) {
      const uint16_t g = Font3x5::glyph(*s);
      for (int r = 0; r < Font3x5::kHeight; ++r)
        for (int c = 0; c < Font3x5::kWidth; ++c) pixel(x + c, y + r, (g >> (r * 3 + c)) & 1u);
      for (int r = 0; r < Font3x5::kHeight; ++r) pixel(x + 3, y + r, false);
    }
    return x;
  }
  // Unsigned decimal.
  int number(int x, int y, uint32_t v) {
    char buf[11];
    int n = 10;
    buf[n] = 0;
    do {
      buf[--n] = static_cast<char>('0' + v % 10);
      v /= 10;
    } while (v != 0 && n > 0);
    return text(x, y, buf + n);
  }
  // Clears one text line of the status column.
  void clearLine(int y) {
    for (int r = 0; r < Font3x5::kHeight + 1; ++r)
      for (int x = kTextX; x < kWidth; ++x) pixel(x, y + r, false);
  }

  // The room map: the grid's window (or the robot's neighbourhood while empty), north up.
  void drawMap(const RoomGrid& grid, Cell robot, Dir heading, bool blinkOn) {
    for (int page = 0; page < kMapSize / 8; ++page) drawMapPage(grid, robot, heading, blinkOn, page);
  }
  // One 8-row band of the map (page 0..7), so a redraw can be spread over several loop passes;
  // the robot and the separator column are drawn with the band that holds them.
  void drawMapPage(const RoomGrid& grid, Cell robot, Dir heading, bool blinkOn, int page) {
    const Bounds w = grid.window();
    const int16_t minX = originX(w, robot), minY = originY(w, robot);
    for (int px = 0; px < kMapSize; ++px) {
      uint8_t column = 0;
      for (int bit = 0; bit < 8; ++bit) {
        const int py = page * 8 + bit;
        const Cell c{static_cast<int16_t>(minX + px), static_cast<int16_t>(minY + (kMapSize - 1 - py))};
        if (!w.contains(c)) continue;
        const CellState st = grid.at(c);
        if (st == CellState::Occupied || (st == CellState::Unknown && (px & 1) == 0 && (py & 1) == 0))
          column = static_cast<uint8_t>(column | (1u << bit));
      }
      f_[page][px] = column;
    }
    f_[page][kMapSize] = 0xFF;  // separator
    const int rx = robot.x - minX, ry = kMapSize - 1 - (robot.y - minY);
    if (rx < 0 || rx >= kMapSize || ry < 0 || ry >= kMapSize) return;
    if (ry / 8 == page) pixel(rx, ry, blinkOn);
    const int hx = rx + dx(heading), hy = ry - dy(heading);
    if (hx >= 0 && hx < kMapSize && hy >= 0 && hy / 8 == page) pixel(hx, hy, true);
  }
  // Only the robot's blinking pixel (cheap; between map redraws).
  void drawRobot(const RoomGrid& grid, Cell robot, bool blinkOn) {
    const Bounds w = grid.window();
    const int rx = robot.x - originX(w, robot), ry = kMapSize - 1 - (robot.y - originY(w, robot));
    if (rx >= 0 && rx < kMapSize && ry >= 0 && ry < kMapSize) pixel(rx, ry, blinkOn);
  }

 private:
  static int16_t originX(const Bounds& w, Cell robot) {
    return w.empty() ? static_cast<int16_t>(robot.x - kMapSize / 2) : w.minX;
  }
  static int16_t originY(const Bounds& w, Cell robot) {
    return w.empty() ? static_cast<int16_t>(robot.y - kMapSize / 2) : w.minY;
  }

  Frame& f_;
};

}  // namespace nxtmap::fw
