#include "common/house/RoomConfinement.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap {
namespace {

bool overlaps(const Doorway& a, const Doorway& b) {
  for (int16_t i = 0; i < a.width; ++i) {
    for (int16_t j = 0; j < a.depth; ++j) {
      if (b.contains(a.cell(i, j))) return true;
    }
  }
  return false;
}

// The line of cells just outside doorway `d` on its far side (beyond +depth when the room is on
// the low side, else beyond -1): where the exit is held shut while the robot stands in it.
Doorway lineBeyond(const Doorway& d, bool roomOnLowSide) {
  Doorway line = d;
  line.first = d.cell(0, roomOnLowSide ? d.depth : static_cast<int16_t>(-1));
  line.depth = 1;
  return line;
}

int16_t clampTo(int v, int lo, int hi) { return static_cast<int16_t>(v < lo ? lo : (v > hi ? hi : v)); }

}  // namespace

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

bool RoomConfinement::wellSeen(const MapLayers& map, const Doorway& d) const {
  // Under noise one stray reading can open a gap in a wall or put a "jamb" in the open: the
  // jambs must be surely occupied and every gap cell surely free.
  const auto jamb = [&](Cell c) { return map.evidence(c) >= kSureEvidence; };
  for (int16_t b = 0; b < d.depth; ++b) {
    if (!jamb(d.cell(-1, b)) || !jamb(d.cell(d.width, b))) return false;
    for (int16_t a = 0; a < d.width; ++a) {
      if (map.evidence(d.cell(a, b)) > -kSureEvidence) return false;
    }
  }
  return true;
}

bool RoomConfinement::isExit(const Doorway& d) const {
  for (uint8_t i = 0; i < exitCount_; ++i) {
    if (overlaps(d, exits_[i].door) || overlaps(exits_[i].door, d)) return true;
  }
  return false;
}

void RoomConfinement::remember(const Doorway& d, bool& changed) {
  bool known = false;
  for (uint8_t i = 0; i < candidateCount_; ++i) {
    Doorway& c = candidates_[i];
    if (!overlaps(d, c) && !overlaps(c, d)) continue;
    known = true;
    if (!(c == d)) {
      c = d;
      changed = true;
    }
  }
  if (known) return;
  if (candidateCount_ == kMaxCandidates) {
    ++overflow_;
    return;
  }
  candidates_[candidateCount_++] = d;
  changed = true;
}

void RoomConfinement::look(MapLayers& map, Cell robot) {
  const int16_t r = static_cast<int16_t>(lookCells_ + limits_.maxWidth + 2);
  const Bounds win = map.grid().window();
  const Bounds area{clampTo(robot.x - r, win.minX, 32767), clampTo(robot.y - r, win.minY, 32767),
                    clampTo(robot.x + r, -32768, win.maxX), clampTo(robot.y + r, -32768, win.maxY)};
  const uint8_t n = findDoorways(map.grid(), area, limits_, found_, kMaxFound);
  bool changed = false;
  for (uint8_t i = 0; i < n; ++i) {
    if (wellSeen(map, found_[i]) && !isExit(found_[i])) remember(found_[i], changed);
  }
  if (!(robot == here_)) {  // moved on: the cell left behind is the robot's side unless a doorway
    if (!closed(here_) && !inCandidate(here_)) outside_ = here_;
    here_ = robot;
  }
  lookWhereStanding(map, robot, changed);
  const bool crowded = exitCount_ > 0 && map.grid().full();  // what lies beyond the exits may be taking room
  if (changed || (++sinceCheck_ >= kRecheckSteps && (candidateCount_ > 0 || crowded))) evaluate(map, robot);
}

// Seen from inside a gap, a doorway in a wall has the room's free space in front of the wall beside
// both jambs, on the side the robot came from; a corridor's cross-section has the corridor's walls
// there. kOpenBeside cells beside each jamb must be free.
bool RoomConfinement::openBeforeJambs(const MapLayers& map, const Doorway& d) const {
  const int16_t line = d.alongX ? d.first.y : d.first.x;
  const int16_t came = d.alongX ? outside_.y : outside_.x;
  if (came == line) return false;
  const int16_t across = came < line ? static_cast<int16_t>(-1) : d.depth;
  for (int16_t k = 1; k <= kOpenBeside; ++k) {
    if (!map.grid().isFree(d.cell(static_cast<int16_t>(-k), across))) return false;
    if (!map.grid().isFree(d.cell(static_cast<int16_t>(d.width - 1 + k), across))) return false;
  }
  return true;
}

// Driven straight into a doorway, the robot sees its jambs only from inside it, one cell of each:
// a gap around the robot on its own row or column counts with jambs of one cell.
void RoomConfinement::lookWhereStanding(MapLayers& map, Cell robot, bool& changed) {
  DoorwayLimits near = limits_;
  near.minJamb = 1;
  const int16_t r = static_cast<int16_t>(limits_.maxWidth + 1);
  const Bounds lines[2] = {
      Bounds{static_cast<int16_t>(robot.x - r), robot.y, static_cast<int16_t>(robot.x + r), robot.y},
      Bounds{robot.x, static_cast<int16_t>(robot.y - r), robot.x, static_cast<int16_t>(robot.y + r)}};
  for (const Bounds& area : lines) {
    const uint8_t n = findDoorways(map.grid(), area, near, found_, kMaxFound);
    for (uint8_t i = 0; i < n; ++i) {
      const Doorway& d = found_[i];
      if (d.contains(robot) && openBeforeJambs(map, d) && wellSeen(map, d) && !isExit(d)) remember(d, changed);
    }
  }
}

void RoomConfinement::evaluate(MapLayers& map, Cell robot) {
  sinceCheck_ = 0;
  // Close every candidate at once (several doorways may lead into the same room), then keep as
  // exits those whose far side is cut off from the start while the robot is on the start's side.
  flood(map.grid(), kShut | kCandidates);
  if (!reached(robotSide(robot))) return;  // the robot is beyond some doorway: decide later
  uint8_t still = 0;
  for (uint8_t i = 0; i < candidateCount_; ++i) {
    const Doorway d = candidates_[i];
    bool low = false, high = false;
    for (int16_t a = 0; a < d.width; ++a) {
      low = low || reached(d.cell(a, -1));
      high = high || reached(d.cell(a, d.depth));
    }
    if (low == high || exitCount_ == kMaxExits) {
      if (low != high) ++overflow_;
      candidates_[still++] = d;
      continue;
    }
    RoomExit& e = exits_[exitCount_];
    e.door = d;
    const int16_t mid = static_cast<int16_t>((d.width - 1) / 2);
    e.inside = low ? d.cell(mid, -1) : d.cell(mid, d.depth);
    e.outward = d.alongX ? (low ? Dir::North : Dir::South) : (low ? Dir::East : Dir::West);
    shut_[exitCount_++] = d.contains(robot) ? lineBeyond(d, low) : d;
  }
  candidateCount_ = still;
  hold(map);
  if (exitCount_ > 0 && map.grid().full()) forgetBeyondExits(map);
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
