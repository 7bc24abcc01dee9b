#include "common/interpret/RoomInterpretation.hpp"

namespace nxtmap {
namespace {

// Score of a candidate wall line: occupied cells on it whose outward neighbour is unknown
// (the robot never saw past them), plus half a point for other occupied cells on it.
int16_t lineScore(const RoomGrid& g, Side side, int16_t line, const Bounds& w) {
  const bool horizontal = side == Side::North || side == Side::South;
  const int16_t from = horizontal ? w.minX : w.minY, to = horizontal ? w.maxX : w.maxY;
  const int16_t out = (side == Side::North || side == Side::East) ? 1 : -1;
  int16_t score = 0;
  for (int16_t i = from; i <= to; ++i) {
    const Cell c = horizontal ? Cell{i, line} : Cell{line, i};
    if (g.at(c) != CellState::Occupied) continue;
    const Cell beyond =
        horizontal ? Cell{i, static_cast<int16_t>(line + out)} : Cell{static_cast<int16_t>(line + out), i};
    score = static_cast<int16_t>(score + (g.at(beyond) == CellState::Unknown ? 2 : 1));
  }
  return score;
}

int16_t findWall(const RoomGrid& g, Side side, const Bounds& w, int16_t& cells) {
  const bool horizontal = side == Side::North || side == Side::South;
  const bool outwardPositive = side == Side::North || side == Side::East;
  const int16_t lo = horizontal ? w.minY : w.minX, hi = horizontal ? w.maxY : w.maxX;
  int16_t best = outwardPositive ? hi : lo, bestScore = -1;
  // Scan from the outside in; a strictly better line wins, so ties keep the outermost.
  for (int16_t k = 0; k <= hi - lo; ++k) {
    const int16_t line = static_cast<int16_t>(outwardPositive ? hi - k : lo + k);
    const int16_t s = lineScore(g, side, line, w);
    if (s > bestScore) {
      bestScore = s;
      best = line;
    }
  }
  cells = 0;
  const int16_t from = horizontal ? w.minX : w.minY, to = horizontal ? w.maxX : w.maxY;
  for (int16_t i = from; i <= to; ++i) {
    if (g.at(horizontal ? Cell{i, best} : Cell{best, i}) == CellState::Occupied) ++cells;
  }
  return best;
}

void addExit(RoomInterpretation& r, Side side, Cell first, int16_t width) {
  if (r.exitCount >= RoomInterpretation::kMaxExits) {
    r.moreExits = true;
    return;
  }
  Exit& e = r.exits[r.exitCount++];
  e.side = side;
  e.first = first;
  e.width = width;
}

// Doorways strictly inside the walls' box become exits on the side of the nearer parallel wall.
void addInnerDoorways(const RoomGrid& grid, const DoorwayLimits& limits, RoomInterpretation& r) {
  const Bounds inner{static_cast<int16_t>(r.wallLine[3] + 1), static_cast<int16_t>(r.wallLine[2] + 1),
                     static_cast<int16_t>(r.wallLine[1] - 1), static_cast<int16_t>(r.wallLine[0] - 1)};
  constexpr uint8_t kCap = RoomInterpretation::kMaxExits;
  Doorway found[kCap];
  bool more = false;
  const uint8_t n = findDoorways(grid, inner, limits, found, kCap, &more);
  if (more) r.moreExits = true;
  for (uint8_t i = 0; i < n; ++i) {
    const Doorway& d = found[i];
    // A "doorway" from one outer wall to the opposite one is a cross-section of a narrow room.
    const bool wallToWall = d.alongX ? (d.first.x - 1 == r.wallLine[3] && d.first.x + d.width == r.wallLine[1])
                                     : (d.first.y - 1 == r.wallLine[2] && d.first.y + d.width == r.wallLine[0]);
    if (wallToWall) continue;
    Side side;
    if (d.alongX) {
      side = (r.wallLine[0] - d.first.y) <= (d.first.y - r.wallLine[2]) ? Side::North : Side::South;
    } else {
      side = (r.wallLine[1] - d.first.x) <= (d.first.x - r.wallLine[3]) ? Side::East : Side::West;
    }
    addExit(r, side, d.first, d.width);
  }
}

int32_t insideFree(const RoomGrid& grid, const RoomInterpretation& r) {
  int32_t n = 0;
  for (int16_t y = static_cast<int16_t>(r.wallLine[2] + 1); y < r.wallLine[0]; ++y) {
    for (int16_t x = static_cast<int16_t>(r.wallLine[3] + 1); x < r.wallLine[1]; ++x) {
      if (grid.isFree(Cell{x, y})) ++n;
    }
  }
  return n;
}

uint8_t parts(int16_t interior, int16_t maxSide) {
  if (maxSide <= 0 || interior <= 0) return 1;
  const int p = (interior + maxSide - 1) / maxSide;
  return static_cast<uint8_t>(p > 255 ? 255 : p);
}

}  // namespace

Cell Exit::middle() const {
  const int16_t half = static_cast<int16_t>((width - 1) / 2);
  const bool horizontal = side == Side::North || side == Side::South;
  return horizontal ? Cell{static_cast<int16_t>(first.x + half), first.y}
                    : Cell{first.x, static_cast<int16_t>(first.y + half)};
}

RoomInterpretation interpretRoom(const RoomGrid& grid, const RoomLimits& limits, const DoorwayLimits& doorways) {
  RoomInterpretation r;
  const Bounds w = grid.window();
  if (w.empty() || grid.count(CellState::Occupied) == 0) return r;
  for (int s = 0; s < 4; ++s) {
    r.wallLine[s] = findWall(grid, static_cast<Side>(s), w, r.wallCells[s]);
  }
  r.valid = r.wallLine[0] > r.wallLine[2] && r.wallLine[1] > r.wallLine[3];
  if (!r.valid) return r;
  // Exits: runs of free cells on each wall line, between the corners.
  for (int s = 0; s < 4; ++s) {
    const Side side = static_cast<Side>(s);
    const bool horizontal = side == Side::North || side == Side::South;
    const int16_t from = static_cast<int16_t>((horizontal ? r.wallLine[3] : r.wallLine[2]) + 1);
    const int16_t to = static_cast<int16_t>((horizontal ? r.wallLine[1] : r.wallLine[0]) - 1);
    int16_t runStart = 0, runLen = 0;
    for (int16_t i = from; i <= to + 1; ++i) {
      const Cell c = horizontal ? Cell{i, r.wallLine[s]} : Cell{r.wallLine[s], i};
      const bool open = i <= to && grid.at(c) == CellState::Free;
      if (open) {
        if (runLen == 0) runStart = i;
        ++runLen;
        continue;
      }
      if (runLen > 0) {
        addExit(r, side, horizontal ? Cell{runStart, r.wallLine[s]} : Cell{r.wallLine[s], runStart}, runLen);
        runLen = 0;
      }
    }
  }
  addInnerDoorways(grid, doorways, r);
  r.freeCells = insideFree(grid, r);
  const int16_t iw = r.interiorWidth(), ih = r.interiorHeight();
  r.partsX = parts(iw, limits.maxSide);
  r.partsY = parts(ih, limits.maxSide);
  if (iw < limits.minSide || ih < limits.minSide) {
    r.roomClass = RoomClass::TooSmall;
  } else if (iw > limits.maxSide || ih > limits.maxSide) {
    r.roomClass = RoomClass::TooLarge;
  } else {
    r.roomClass = RoomClass::Room;
  }
  return r;
}

}  // namespace nxtmap
