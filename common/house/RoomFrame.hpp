// RoomFrame: cells of one room's frame seen from a pose in another's. A new room's frame has its
// origin where the robot stands when it starts the room and +y along its heading there (+x to its
// right), like every explorer's start; these turn cells, directions and doorways of the room it
// came from (the pose's frame) into the new room's frame. Whole cells and quarter turns: exact.
#pragma once

#include "common/explore/Pose.hpp"
#include "common/grid/Cell.hpp"
#include "common/interpret/Doorway.hpp"

namespace nxtmap {

// Cell `c` of the old frame in the frame whose origin is `origin` (a pose in the old frame).
constexpr Cell intoFrame(Cell c, const Pose& origin) {
  const int ex = c.x - origin.cell.x, ey = c.y - origin.cell.y;
  const Dir up = origin.heading, right = rotate(origin.heading, 1);
  return Cell{static_cast<int16_t>(ex * dx(right) + ey * dy(right)), static_cast<int16_t>(ex * dx(up) + ey * dy(up))};
}

// Direction `d` of the old frame in the frame facing `heading` (old frame) along its +y.
constexpr Dir intoFrame(Dir d, Dir heading) { return rotate(d, -static_cast<int>(heading)); }

// A doorway of the old frame in the new one (the same cells, from their new lowest corner).
inline Doorway intoFrame(const Doorway& door, const Pose& origin) {
  const Cell a = intoFrame(door.cell(0, 0), origin);
  const Cell b =
      intoFrame(door.cell(static_cast<int16_t>(door.width - 1), static_cast<int16_t>(door.depth - 1)), origin);
  Doorway d;
  d.alongX = isVertical(origin.heading) ? door.alongX : !door.alongX;
  d.first = Cell{a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y};
  d.width = door.width;
  d.depth = door.depth;
  return d;
}

}  // namespace nxtmap
