// RoomConfinement's doorways: which gaps in the room's walls, seen well enough, are its exits (remembered, and
// held shut while the robot maps the room), including one the robot stands in.
#include "common/house/RoomConfinement.hpp"

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

}  // namespace nxtmap
