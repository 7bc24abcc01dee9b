// RunTrace: the robot's pose as it believes it and as it truly is, after every action of a mapping run, so a
// lost run shows where it went astray (`nxtmap sim --trace FILE.csv`).
//
// All in the explorer's frame: origin the centre of the start cell, +y the start heading, +x to its right,
// millimetres; headings milliradians, + clockwise, from the explorer's north. The belief is the explorer's cell
// and heading plus the pose tracker's offset within that cell; the truth is the simulated robot's centre and
// heading on the truth raster's grid (after the start's sweep, the grid it was laid on again).
#pragma once

#include <cstdint>
#include <ostream>

#include "common/motion/DriveAction.hpp"
#include "common/sensing/RangeReading.hpp"

namespace nxtmap::mapping {

class MappingRun;

struct TracePose {
  double trueXMm = 0, trueYMm = 0, trueThetaMrad = 0;  // the robot's centre and heading
  int cellX = 0, cellY = 0, headingQuarters = 0;       // the explorer's cell and heading (0 N, 1 E, 2 S, 3 W)
  int32_t estXMm = 0, estYMm = 0, estThetaMrad = 0;    // the tracker's offset from the cell's centre and axis
  double errXMm = 0, errYMm = 0, errThetaMrad = 0;     // truth minus belief
  double sdXMm = 0, sdYMm = 0, sdThetaMrad = 0;        // the tracker's own 1 sigma of its offset and heading
  bool mapping = false;                                // the explorer has started (the start's sweep is over)
  bool lost = false;                                   // the centre lies in another cell than the believed one
};

// The names a trace gives an action and a reading's status (read, rotate, drive, done, think; good, no-echo,
// too-near, too-far, inconsistent).
const char* actionName(DriveAction::Kind k);
const char* statusName(RangeStatus s);

// The belief and the truth of `run` as it stands now.
TracePose tracePose(const MappingRun& run);

// Writes one CSV row per action (for a reading also its sensor, F R B L, its cm and its status) and, at the
// end, a summary of where the belief first left the robot's cell and how often the error was larger than the
// tracker believed it could be (a consistent filter: about 1 action in 100 outside its 3 sigma).
class RunTrace {
 public:
  explicit RunTrace(std::ostream& out);
  // The pose after action number `step` (1 the first), `done`, was carried out.
  void record(const MappingRun& run, uint64_t step, const DriveAction& done);
  // Actions recorded while the believed cell was not the robot's; the first such step (0: never).
  uint64_t lostSteps() const { return lostSteps_; }
  uint64_t firstLostStep() const { return firstLost_; }
  // Actions since the explorer started, and of them those whose error along x, y or in heading exceeded 3 of the
  // tracker's sigma (and the whole mm or mrad the columns are rounded to).
  uint64_t mappingSteps() const { return mappingSteps_; }
  uint64_t outsideSteps() const { return outsideSteps_; }
  // The largest position error seen, mm (Euclidean), and heading error, mrad (absolute).
  double worstErrorMm() const { return worstMm_; }
  double worstErrorMrad() const { return worstMrad_; }

 private:
  std::ostream& out_;
  uint64_t lostSteps_ = 0, firstLost_ = 0, mappingSteps_ = 0, outsideSteps_ = 0;
  double worstMm_ = 0, worstMrad_ = 0;
};

}  // namespace nxtmap::mapping
