// BestFramesScore: how much of a mapped house's disagreement with the world is its room frames and how
// much the room maps themselves. Each room's frame is moved by whole cells (each axis within +-maxShift
// house cells of where it was put) to where the house agrees best with the world: coordinate ascent, the
// rooms in order, until a whole pass moves none (at most kMaxPasses). Knows the world: a measure for
// tests and benchmarks, never an input to mapping.
//
// The score is the maps' quality apart from their joining (two houses whose rooms were mapped alike
// but joined a cell apart score alike); HouseScore's agreement less this one's is what the frames cost.
#pragma once

#include <vector>

#include "common/grid/Cell.hpp"
#include "host/house/HouseScore.hpp"

namespace nxtmap::house {

struct BestFramesScore {
  HouseScore score;          // every room at its best frame
  std::vector<Cell> shifts;  // per room (network order): the move to its best frame, house cells
  int passes = 0;            // coordinate-ascent passes made, 1..kMaxPasses
  static constexpr int kMaxPasses = 6;
};

// `house.network` is not changed: the frames are moved in a copy.
BestFramesScore scoreWithBestFrames(const HouseInWorld& house, int maxShift = 2);

}  // namespace nxtmap::house
