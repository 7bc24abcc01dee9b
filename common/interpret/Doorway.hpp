#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/RoomGrid.hpp"

namespace nxtmap {

// A doorway: a gap of free cells in a wall, between two wall ends ("jambs") on one line.
// alongX: the gap runs along x (a gap in a wall parallel to x, crossed by moving North/South);
// otherwise it runs along y. Thick walls give several parallel lines with the same gap: `depth`.
struct Doorway {
  bool alongX = true;
  Cell first{};       // lowest cell of the gap on its lowest line
  int16_t width = 0;  // cells along the wall, >= 1
  int16_t depth = 1;  // cells across the wall (wall thickness), >= 1

  // The cell `along` cells along the gap and `across` cells across it from `first`
  // (across may be negative or >= depth for the cells on either side of the doorway).
  constexpr Cell cell(int16_t along, int16_t across) const {
    return alongX ? offset(first, along, across) : offset(first, across, along);
  }
  constexpr Cell middle() const { return cell(static_cast<int16_t>((width - 1) / 2), 0); }
  constexpr bool contains(Cell c) const {
    const int a = alongX ? c.x - first.x : c.y - first.y;
    const int b = alongX ? c.y - first.y : c.x - first.x;
    return a >= 0 && a < width && b >= 0 && b < depth;
  }
  constexpr bool operator==(const Doorway& o) const {
    return alongX == o.alongX && first == o.first && width == o.width && depth == o.depth;
  }
};

// Doorway sizes in cells.
struct DoorwayLimits {
  int16_t minWidth = 2;   // narrower gaps are taken as sensing holes
  int16_t maxWidth = 15;  // wider gaps are open areas, not doorways (1.5 m at 10 cm cells)
  int16_t maxDepth = 3;   // deeper "gaps" are corridors
  int16_t minJamb = 1;    // occupied cells each wall end must show along the line (2+: a stray
                          // occupied cell in the open is no jamb)
};

// Finds the doorways whose cells lie in `area` (usually the grid's window). A doorway is a run of
// known-free cells on a line, between two occupied jambs on the same line, where each jamb is the
// end of a wall along that line (not the side of a wall across it): of a jamb's two neighbours
// across the line, at least one is free and not both are occupied; and the wall goes on along the
// line away from the gap for minJamb occupied cells. The cells just outside the
// gap's middle on both sides must not be occupied (the doorway can be crossed).
// Writes at most `capacity` doorways to `out` and returns how many; `more` (optional) tells
// whether some were left out.
uint8_t findDoorways(const RoomGrid& grid, const Bounds& area, const DoorwayLimits& limits, Doorway* out,
                     uint8_t capacity, bool* more = nullptr);

}  // namespace nxtmap
