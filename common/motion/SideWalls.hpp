#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// What two readings of one wall beside the robot's path say about its heading (SideWalls::pair).
struct SideSlope {
  int32_t errorMrad = 0;  // the heading error the readings show, mrad, + clockwise (as PoseTracker's theta)
  int32_t baseMm = 0;     // how far apart along the wall they were taken, mm (signed)
  uint16_t turns = 0;     // quarter turns made between them
  uint16_t acrossPathMm = 0;  // driven towards or away from the wall between them (its own slip), mm
};

// SideWalls: the walls the robot read beside its path, remembered so that a wall read again further along it
// measures the heading. A wall straight and square to the map (rectilinear rooms, a squared start) lies at a
// fixed distance across; moving base mm along it (counted positive in the direction that has the wall on the
// right) with a heading error e (+ clockwise) takes the robot base * e nearer it than the wheels tell, so the
// range falls by that much more than the wheels say it should.
//
// Positions are dead-reckoned: where the robot is by its wheels and the heading it believed (drove), never moved
// by readings, in mm east and north of an arbitrary origin in the explorer's frame, kept modulo 2^16 (a pair
// spans well under 32 m). Walls are told apart by their row or column of cells (the caller's `line`) and their
// side (the Dir they are seen along). Each side remembers its last kMarks walls, kept across turns: a path that
// zigzags (a quarter turn every cell or two) reads the same wall again after each turn back. A wall read again
// too near the reading held keeps the older one (the longer base).
//
// Also the side-reading policy's memory of the current run (since the last quarter turn): whether and where
// each side was last read in it. 10 bytes per side and mark, 4 per side, 10 more; owned by the pilot.
class SideWalls {
 public:
  static constexpr int kMarks = 2;  // walls remembered per side

  // Forgets every wall (a new start: another frame).
  void clear();
  // The robot drove mm (signed) facing `heading`, believed thetaMrad off it (+ clockwise).
  void drove(Dir heading, int32_t mm, int32_t thetaMrad);
  // A quarter turn: a new run.
  void turned();

  // The side d was read in this run (any reading).
  void tried(Dir d);
  // A good reading of the wall in `line` seen along d: the pair it makes with the reading of that wall held
  // (when at least minBaseMm apart along it) goes into `slope` (returns true); the reading is then held.
  bool pair(Dir d, int16_t line, int32_t rangeMm, int32_t minBaseMm, SideSlope& slope);

  // The policy: a wall of side d was read in this run (held), how far along it the robot has come since that
  // reading, or since the side was last tried in this run (mm), and whether it was tried at all.
  bool held(Dir d) const;
  int32_t sinceMm(Dir d) const;
  bool triedInRun(Dir d) const { return runs_[static_cast<int>(d)].tried; }

 private:
  static constexpr int16_t kNoLine = -32768;
  struct Mark {
    int16_t sumMm = 0;     // the range plus the position towards the wall (their sum stays put)
    int16_t alongMm = 0;   // position along the wall, towards rotate(d, -1) (d on the right)
    int16_t line = kNoLine;
    uint16_t turns = 0;    // turns_ at the reading
    uint16_t pathMm = 0;   // pathMm_ across the wall (along d's axis) at the reading
  };
  struct Run {
    int16_t triedMm = 0;  // position along the wall when the side was last tried
    uint8_t latest = 0;   // the mark of the last good reading
    bool tried = false;
  };
  int16_t along(Dir d) const;
  int16_t across(Dir d) const;

  Mark marks_[4][kMarks];  // by Dir
  Run runs_[4];            // by Dir
  int16_t xMm_ = 0, yMm_ = 0;
  uint16_t pathMm_[2] = {0, 0};  // driven along the x and the y axis, mm (either way, modulo 2^16)
  uint16_t turns_ = 0;
};
static_assert(sizeof(SideWalls) <= 4 * (SideWalls::kMarks * 10 + 4) + 10, "SideWalls: 106 bytes on the brick");

}  // namespace nxtmap
