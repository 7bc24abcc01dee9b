#include "common/house/RoomConfinement.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap {

NXTMAP_RUN_ONCE RoomConfinement::RoomConfinement(uint8_t* reachBits, int16_t width, int16_t height,
                                                 const DoorwayLimits& limits, int16_t lookCells)
    : reachBits_(reachBits), width_(width), height_(height), limits_(limits), lookCells_(lookCells) {}

void RoomConfinement::begin(const Doorway* entrance) {
  hasEntrance_ = entrance != nullptr;
  exitCount_ = 0;
  candidateCount_ = 0;
  sinceCheck_ = 0;
  overflow_ = 0;
  reachBox_ = Bounds{};
  outside_ = here_ = Cell{};
  guards_[0] = guards_[1] = Doorway{};
  if (!hasEntrance_) return;
  entrance_ = *entrance;
  // Under noise a doorway can be found a cell or two narrower than it is, and the robot would slip
  // back past its closed cells into the room it came from: the line goes on closed for kGuardCells.
  const Cell a = entrance_.cell(0, 0);
  const Cell b = entrance_.cell(static_cast<int16_t>(entrance_.width - 1), static_cast<int16_t>(entrance_.depth - 1));
  const Bounds box{a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.x < b.x ? b.x : a.x, a.y < b.y ? b.y : a.y};
  const bool alongX = box.width() >= box.height();
  for (int end = 0; end < 2; ++end) {
    Doorway& g = guards_[end];
    g.alongX = alongX;
    g.width = kGuardCells;
    g.depth = alongX ? box.height() : box.width();
    if (alongX)
      g.first = Cell{static_cast<int16_t>(end == 0 ? box.minX - kGuardCells : box.maxX + 1), box.minY};
    else
      g.first = Cell{box.minX, static_cast<int16_t>(end == 0 ? box.minY - kGuardCells : box.maxY + 1)};
  }
}

bool RoomConfinement::closed(Cell c) const {
  if (hasEntrance_ && entrance_.contains(c)) return true;
  for (uint8_t i = 0; i < exitCount_; ++i) {
    if (exits_[i].door.contains(c) || shut_[i].contains(c)) return true;
  }
  return false;
}

bool RoomConfinement::contains(Cell c) const {
  if (hasEntrance_ && (entrance_.contains(c) || guards_[0].contains(c) || guards_[1].contains(c))) return true;
  for (uint8_t i = 0; i < exitCount_; ++i) {
    if (shut_[i].contains(c)) return true;
  }
  return false;
}

bool RoomConfinement::inCandidate(Cell c) const {
  for (uint8_t i = 0; i < candidateCount_; ++i) {
    if (candidates_[i].contains(c)) return true;
  }
  return false;
}

Cell RoomConfinement::robotSide(Cell robot) const { return closed(robot) || inCandidate(robot) ? outside_ : robot; }

void RoomConfinement::hold(MapLayers& map) const {
  const auto block = [&](const Doorway& d) {
    for (int16_t a = 0; a < d.width; ++a) {
      for (int16_t b = 0; b < d.depth; ++b) (void)map.markBlocked(d.cell(a, b));
    }
  };
  if (hasEntrance_) {
    block(entrance_);
    block(guards_[0]);
    block(guards_[1]);
  }
  for (uint8_t i = 0; i < exitCount_; ++i) block(shut_[i]);
}

// Every Drive carries out one explorer move of one cell (forward for value > 0).
bool RoomConfinement::drivesIntoShut(const Pose& p, const DriveAction& a) const {
  if (a.kind != DriveAction::Kind::Drive) return false;
  return contains(advance(p.cell, a.value > 0 ? p.heading : opposite(p.heading)));
}

void RoomConfinement::forgetBeyondExits(MapLayers& map) {
  // Kept: what the start reaches through anything but the closed doors (a candidate is still open: what lies
  // beyond it may be this room's), the cells next to that (its walls) and what is shut.
  flood(map.grid(), kShut);
  const auto nearReached = [&](Cell c) {
    for (int16_t dy = -1; dy <= 1; ++dy) {
      for (int16_t dx = -1; dx <= 1; ++dx) {
        if (reached(Cell{static_cast<int16_t>(c.x + dx), static_cast<int16_t>(c.y + dy)})) return true;
      }
    }
    return false;
  };
  bool forgot = false;
  for (int16_t y = reachBox_.minY; y <= reachBox_.maxY; ++y) {
    for (int16_t x = reachBox_.minX; x <= reachBox_.maxX; ++x) {
      const Cell c{x, y};
      if (map.grid().isUnknown(c) || contains(c) || closed(c) || nearReached(c)) continue;
      map.forget(c);
      forgot = true;
    }
  }
  if (forgot) map.grid().shrink();
}

void RoomConfinement::finish(MapLayers& map) {
  // Open the doors again: they are free (they were seen free before they were closed).
  const auto open = [&](const Doorway& d) {
    for (int16_t a = 0; a < d.width; ++a) {
      for (int16_t b = 0; b < d.depth; ++b) {
        const Cell c = d.cell(a, b);
        for (int k = 0; k < 16 && map.grid().isOccupied(c); ++k) (void)map.observeFree(c);
      }
    }
  };
  if (hasEntrance_) open(entrance_);
  for (uint8_t i = 0; i < exitCount_; ++i) open(shut_[i]);
  flood(map.grid(), kDoors);
  // An exit found while the robot was beyond another doorway may join two other rooms: only the
  // exits of this room (their inside cell reached) are kept; the others are found again there.
  uint8_t kept = 0;
  for (uint8_t i = 0; i < exitCount_; ++i) {
    if (!reached(exits_[i].inside)) continue;
    shut_[kept] = shut_[i];
    exits_[kept++] = exits_[i];
  }
  exitCount_ = kept;
}

bool RoomConfinement::seen(Cell c) const {
  if (!reachBox_.contains(c)) return false;
  const int i = (c.y - reachBox_.minY) * reachBox_.width() + (c.x - reachBox_.minX);
  return (reachBits_[i >> 3] >> (i & 7)) & 1u;
}

void RoomConfinement::see(Cell c) {
  const int i = (c.y - reachBox_.minY) * reachBox_.width() + (c.x - reachBox_.minX);
  reachBits_[i >> 3] = static_cast<uint8_t>(reachBits_[i >> 3] | (1u << (i & 7)));
}

bool RoomConfinement::reached(Cell c) const { return seen(c); }

void RoomConfinement::flood(const RoomGrid& grid, uint8_t stop) {
  const auto blocked = [&](Cell c) {
    return closed(c) || ((stop & kShut) != 0 && contains(c)) || ((stop & kCandidates) != 0 && inCandidate(c));
  };
  reachBox_ = grid.window();
  if (reachBox_.width() * reachBox_.height() > width_ * height_) reachBox_ = Bounds{};  // never: the window fits
  const int cells = reachBox_.width() * reachBox_.height();
  for (int i = 0; i < (cells + 7) / 8; ++i) reachBits_[i] = 0;
  // The start cell always counts (the robot stood there), whatever noise later said about it.
  const Cell start{0, 0};
  if (!reachBox_.contains(start)) return;
  see(start);
  const auto grow = [&](Cell c) {
    if (seen(c) || !grid.isFree(c) || blocked(c)) return false;
    for (int d = 0; d < 4; ++d) {
      if (seen(advance(c, static_cast<Dir>(d)))) {
        see(c);
        return true;
      }
    }
    return false;
  };
  // Raster sweeps forward and back until nothing grows: the cells connected to the start.
  for (bool grew = true; grew;) {
    grew = false;
    for (int16_t y = reachBox_.minY; y <= reachBox_.maxY; ++y) {
      for (int16_t x = reachBox_.minX; x <= reachBox_.maxX; ++x) grew = grow(Cell{x, y}) || grew;
    }
    for (int16_t y = reachBox_.maxY; y >= reachBox_.minY; --y) {
      for (int16_t x = reachBox_.maxX; x >= reachBox_.minX; --x) grew = grow(Cell{x, y}) || grew;
    }
  }
}

}  // namespace nxtmap
