#pragma once
#include "common/grid/Cell.hpp"
#include "host/sim/Heading.hpp"

namespace nxtmap::mapping {

// World cell (col to the right, row down) of the simulator <-> explorer cell (origin at the
// start cell, +y along the robot's initial heading, +x to its right).
class FrameTransform {
 public:
  FrameTransform(int startCol, int startRow, sim::Heading heading);
  void toWorld(Cell c, int& col, int& row) const;
  Cell toExplorer(int col, int row) const;
  // The world heading of an explorer direction.
  sim::Heading toWorld(Dir d) const;

 private:
  int startCol_, startRow_;
  int fwdCol_, fwdRow_, rightCol_, rightRow_;
  sim::Heading heading_;
};

}  // namespace nxtmap::mapping
