#include "common/grid/RoomGrid.hpp"

#include "common/check/Check.hpp"

namespace nxtmap {

RoomGrid::RoomGrid(uint8_t* storage, int16_t capacityWidth, int16_t capacityHeight)
    : cells_(storage, capacityWidth, capacityHeight) {
  NXTMAP_CHECK(isPowerOfTwo(capacityWidth) && isPowerOfTwo(capacityHeight));
  clear();
}

void RoomGrid::clear() {
  cells_.fill(static_cast<uint8_t>(CellState::Unknown));
  window_ = Bounds{};
}

CellState RoomGrid::at(Cell c) const {
  if (!window_.contains(c)) return CellState::Unknown;
  return static_cast<CellState>(cells_.at(c));
}

bool RoomGrid::fits(Cell c) const {
  if (window_.empty()) return true;
  const int32_t minX = c.x < window_.minX ? c.x : window_.minX;
  const int32_t maxX = c.x > window_.maxX ? c.x : window_.maxX;
  const int32_t minY = c.y < window_.minY ? c.y : window_.minY;
  const int32_t maxY = c.y > window_.maxY ? c.y : window_.maxY;
  return maxX - minX < cells_.width() && maxY - minY < cells_.height();
}

bool RoomGrid::set(Cell c, CellState s) {
  if (!fits(c)) return false;
  if (window_.empty()) {
    window_ = Bounds{c.x, c.y, c.x, c.y};
  } else {
    // Invariant: every torus cell outside the window holds Unknown, so growing needs no clearing.
    if (c.x < window_.minX) window_.minX = c.x;
    if (c.x > window_.maxX) window_.maxX = c.x;
    if (c.y < window_.minY) window_.minY = c.y;
    if (c.y > window_.maxY) window_.maxY = c.y;
  }
  cells_.set(c, static_cast<uint8_t>(s));
  return true;
}

void RoomGrid::shrink() {
  Bounds known{};
  for (int16_t y = window_.minY; y <= window_.maxY; ++y) {
    for (int16_t x = window_.minX; x <= window_.maxX; ++x) {
      if (at(Cell{x, y}) == CellState::Unknown) continue;
      if (known.empty()) {
        known = Bounds{x, y, x, y};
        continue;
      }
      if (x < known.minX) known.minX = x;
      if (x > known.maxX) known.maxX = x;
      if (y > known.maxY) known.maxY = y;  // rows run upwards: minY is the first row found
    }
  }
  window_ = known;  // every cell outside it holds Unknown: the invariant of set() holds
}

int32_t RoomGrid::count(CellState s) const {
  int32_t n = 0;
  for (int16_t y = window_.minY; y <= window_.maxY; ++y) {
    for (int16_t x = window_.minX; x <= window_.maxX; ++x) {
      if (at(Cell{x, y}) == s) ++n;
    }
  }
  return n;
}

Cell RoomGrid::restructure() {
  if (window_.empty()) return Cell{0, 0};
  const Cell shift{window_.minX, window_.minY};
  cells_.translate(shift.x, shift.y);
  window_ = Bounds{0, 0, static_cast<int16_t>(window_.maxX - shift.x), static_cast<int16_t>(window_.maxY - shift.y)};
  return shift;
}

}  // namespace nxtmap
