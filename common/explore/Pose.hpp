#pragma once
#include "common/grid/Cell.hpp"

namespace nxtmap {

// The robot's believed cell and heading in the explorer's frame.
struct Pose {
  Cell cell{};
  Dir heading = Dir::North;
};

}  // namespace nxtmap
