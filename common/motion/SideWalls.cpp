#include "common/motion/SideWalls.hpp"

#include "common/math/IntAbs.hpp"

namespace nxtmap {
namespace {

// Positions are kept modulo 2^16 mm: sums and differences wrap the same way (two's complement).
int16_t wrap(int32_t v) { return static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(v) & 0xFFFFu)); }

}  // namespace

void SideWalls::clear() {
  for (auto& side : marks_)
    for (Mark& m : side) m = Mark{};
  for (Run& r : runs_) r = Run{};
}

void SideWalls::drove(Dir heading, int32_t mm, int32_t thetaMrad) {
  const Dir right = rotate(heading, 1);
  const int32_t side = static_cast<int32_t>(static_cast<int64_t>(mm) * thetaMrad / 1000);
  xMm_ = wrap(xMm_ + mm * dx(heading) + side * dx(right));
  yMm_ = wrap(yMm_ + mm * dy(heading) + side * dy(right));
  uint16_t& path = pathMm_[isVertical(heading) ? 1 : 0];
  path = static_cast<uint16_t>(path + static_cast<uint32_t>(abs32(mm)));
}

void SideWalls::turned() {
  ++turns_;
  for (Run& r : runs_) r.tried = false;
}

int16_t SideWalls::along(Dir d) const {
  const Dir a = rotate(d, -1);
  return wrap(dx(a) * xMm_ + dy(a) * yMm_);
}

int16_t SideWalls::across(Dir d) const { return wrap(dx(d) * xMm_ + dy(d) * yMm_); }

void SideWalls::tried(Dir d) {
  Run& r = runs_[static_cast<int>(d)];
  r.tried = true;
  r.triedMm = along(d);
}

bool SideWalls::pair(Dir d, int16_t line, int32_t rangeMm, int32_t minBaseMm, SideSlope& slope) {
  Mark* marks = marks_[static_cast<int>(d)];
  // The mark of this wall; else the one to take the reading: an empty one, or the oldest.
  int at = -1, free = 0;
  for (int i = 0; i < kMarks; ++i) {
    if (marks[i].line == line) at = i;
    const bool older = static_cast<uint16_t>(turns_ - marks[i].turns) > static_cast<uint16_t>(turns_ - marks[free].turns);
    if (marks[free].line != kNoLine && (marks[i].line == kNoLine || older)) free = i;
  }
  const int16_t sum = wrap(rangeMm + across(d));
  const int16_t alongNow = along(d);
  bool paired = false;
  if (at >= 0) {
    const Mark& m = marks[at];
    const int32_t base = wrap(alongNow - m.alongMm);
    if (abs32(base) < minBaseMm) return false;  // too near the reading held: keep the longer base
    // Nearer the wall by (sum then - sum now) more than the wheels tell, over base along it.
    const int32_t unseen = wrap(m.sumMm - sum);
    slope.errorMrad = static_cast<int32_t>(static_cast<int64_t>(unseen) * 1000 / base);
    slope.baseMm = base;
    slope.turns = static_cast<uint16_t>(turns_ - m.turns);
    slope.acrossPathMm = static_cast<uint16_t>(pathMm_[isVertical(d) ? 1 : 0] - m.pathMm);
    paired = true;
  }
  const int k = at >= 0 ? at : free;
  marks[k] = Mark{sum, alongNow, line, turns_, pathMm_[isVertical(d) ? 1 : 0]};
  runs_[static_cast<int>(d)].latest = static_cast<uint8_t>(k);
  return paired;
}

bool SideWalls::held(Dir d) const {
  const Run& r = runs_[static_cast<int>(d)];
  const Mark& m = marks_[static_cast<int>(d)][r.latest];
  return m.line != kNoLine && m.turns == turns_;
}

int32_t SideWalls::sinceMm(Dir d) const {
  const Run& r = runs_[static_cast<int>(d)];
  const int16_t from = held(d) ? marks_[static_cast<int>(d)][r.latest].alongMm : r.triedMm;
  return abs32(wrap(along(d) - from));
}

}  // namespace nxtmap
