// HouseTrace: the robot's pose as it believes it and as it truly is after every action of a house run, so a run
// that lost a room shows where it went astray (`nxtmap sim-house --trace FILE.csv`).
//
// All in the world's raster (the truth on the robot's grid): columns right, rows down, cells of the robot's size;
// the truth's centre in fractional cells and its heading in degrees clockwise from north (the raster's up); the
// belief as the house planner places the brick's frame (the room's, or the travel's) in the world, whole cells and
// N E S W, with the pose tracker's offset (mm, along the brick's frame: +x right of its north, +y ahead) and heading
// error (mrad). `lost` is the truth's centre in another cell than the believed one.
#pragma once

#include <cstdint>
#include <ostream>

#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"

namespace nxtmap::house {

struct HouseTraceRow {
  const char* order = "";  // what the house planner asked: room, travel, cross, scan
  DriveAction done;        // the action carried out
  DriveEvent answer;       // and what it gave (a reading's sensor and range)
  double trueCol = 0, trueRow = 0, trueHeadingDeg = 0;
  bool believed = false;  // a room run or a travel is under way (else nothing is believed yet)
  int believedCol = 0, believedRow = 0;
  char believedHeading = 'N';
  int32_t estXMm = 0, estYMm = 0, estThetaMrad = 0;
  bool lost = false;
};

class HouseTrace {
 public:
  explicit HouseTrace(std::ostream& out);
  void record(const HouseTraceRow& row);
  uint64_t steps() const { return steps_; }
  uint64_t lostSteps() const { return lostSteps_; }
  uint64_t firstLostStep() const { return firstLost_; }  // 0: never

 private:
  std::ostream& out_;
  uint64_t steps_ = 0, lostSteps_ = 0, firstLost_ = 0;
};

}  // namespace nxtmap::house
