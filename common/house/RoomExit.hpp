#pragma once

#include "common/grid/Cell.hpp"
#include "common/interpret/Doorway.hpp"

namespace nxtmap {

// An exit of a room, in the room's frame: the doorway's cells, the room's cell in front of its
// middle, and the direction that leads out through it (crossing door.depth cells).
struct RoomExit {
  Doorway door;
  Cell inside{};
  Dir outward = Dir::North;
};

// The doorway covering the bounding box of `count` cells (a line or a block of cells, e.g. an
// opening onto unknown space): alongX when the box is at least as wide as it is tall.
inline Doorway doorwayAround(const Cell* cells, int count) {
  Bounds b{cells[0].x, cells[0].y, cells[0].x, cells[0].y};
  for (int i = 1; i < count; ++i) {
    b.minX = cells[i].x < b.minX ? cells[i].x : b.minX;
    b.minY = cells[i].y < b.minY ? cells[i].y : b.minY;
    b.maxX = cells[i].x > b.maxX ? cells[i].x : b.maxX;
    b.maxY = cells[i].y > b.maxY ? cells[i].y : b.maxY;
  }
  Doorway d;
  d.alongX = b.width() >= b.height();
  d.first = Cell{b.minX, b.minY};
  d.width = d.alongX ? b.width() : b.height();
  d.depth = d.alongX ? b.height() : b.width();
  return d;
}

}  // namespace nxtmap
