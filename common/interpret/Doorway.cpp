#include "common/interpret/Doorway.hpp"

namespace nxtmap {
namespace {

// The cell at position `along` on line `line` of the given orientation.
constexpr Cell at(bool alongX, int16_t along, int16_t line) { return alongX ? Cell{along, line} : Cell{line, along}; }

// `away`: +1 or -1, the direction along the line that leads away from the gap.
bool isJamb(const RoomGrid& g, bool alongX, int16_t along, int16_t line, int16_t away, int16_t minJamb) {
  for (int16_t k = 0; k < minJamb; ++k) {
    if (!g.isOccupied(at(alongX, static_cast<int16_t>(along + k * away), line))) return false;
  }
  const CellState a = g.at(at(alongX, along, static_cast<int16_t>(line - 1)));
  const CellState b = g.at(at(alongX, along, static_cast<int16_t>(line + 1)));
  const bool bothOccupied = a == CellState::Occupied && b == CellState::Occupied;
  const bool oneFree = a == CellState::Free || b == CellState::Free;
  return oneFree && !bothOccupied;
}

// Adds a one-line gap, merging it with a gap of the same extent on the line below.
void addLine(bool alongX, int16_t from, int16_t width, int16_t line, Doorway* found, uint8_t& n, uint8_t capacity,
             bool& more) {
  for (uint8_t i = 0; i < n; ++i) {
    Doorway& d = found[i];
    const int16_t dFrom = alongX ? d.first.x : d.first.y;
    const int16_t dLine = alongX ? d.first.y : d.first.x;
    if (d.alongX == alongX && dFrom == from && d.width == width && dLine + d.depth == line) {
      ++d.depth;
      return;
    }
  }
  if (n >= capacity) {
    more = true;
    return;
  }
  Doorway& d = found[n++];
  d.alongX = alongX;
  d.first = at(alongX, from, line);
  d.width = width;
  d.depth = 1;
}

bool crossable(const RoomGrid& g, const Doorway& d) {
  const int16_t mid = static_cast<int16_t>((d.width - 1) / 2);
  const CellState a = g.at(d.cell(mid, -1));
  const CellState b = g.at(d.cell(mid, d.depth));
  if (a == CellState::Occupied || b == CellState::Occupied) return false;
  return a == CellState::Free || b == CellState::Free;
}

}  // namespace

uint8_t findDoorways(const RoomGrid& grid, const Bounds& area, const DoorwayLimits& limits, Doorway* out,
                     uint8_t capacity, bool* more) {
  uint8_t n = 0;
  bool overflow = false;
  if (area.empty() || capacity == 0) {
    if (more) *more = false;
    return 0;
  }
  for (int o = 0; o < 2; ++o) {
    const bool alongX = o == 0;
    const int16_t lineLo = alongX ? area.minY : area.minX, lineHi = alongX ? area.maxY : area.maxX;
    const int16_t lo = alongX ? area.minX : area.minY, hi = alongX ? area.maxX : area.maxY;
    for (int16_t line = lineLo; line <= lineHi; ++line) {
      int16_t runStart = 0, runLen = 0;
      for (int16_t i = lo; i <= hi + 1; ++i) {
        if (i <= hi && grid.isFree(at(alongX, i, line))) {
          if (runLen == 0) runStart = i;
          ++runLen;
          continue;
        }
        if (runLen >= limits.minWidth && runLen <= limits.maxWidth &&
            isJamb(grid, alongX, static_cast<int16_t>(runStart - 1), line, -1, limits.minJamb) &&
            isJamb(grid, alongX, i, line, 1, limits.minJamb)) {
          addLine(alongX, runStart, runLen, line, out, n, capacity, overflow);
        }
        runLen = 0;
      }
    }
  }
  // Keep the doorways that are not too deep and can be crossed.
  uint8_t kept = 0;
  for (uint8_t i = 0; i < n; ++i) {
    if (out[i].depth > limits.maxDepth || !crossable(grid, out[i])) continue;
    out[kept++] = out[i];
  }
  if (more) *more = overflow;
  return kept;
}

}  // namespace nxtmap
