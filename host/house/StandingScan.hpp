// StandingScan: where the robot really stands, when travel found a wall the map does not have
// there: readings taken in the four directions from one spot are matched against the known map at
// whole-cell shifts of the believed cell. Used to recover a robot that is lost by a cell or more
// (a pose error beyond what the pilot's gate lets a reading correct).
#pragma once

#include <vector>

#include "common/grid/Cell.hpp"
#include "common/sensing/RangeGeometry.hpp"
#include "host/network/RoomMap.hpp"

namespace nxtmap::house {

// One filtered reading taken where the robot stands, in the map's frame.
struct StandingReading {
  Dir dir = Dir::North;  // where the sensor looked
  bool echo = false;     // false: nothing within reach
  int cm = 0;            // echo distance from the sensor face, cm (echo only)
};

// Score of the robot standing in `at`: +2 per echo that lands on a known wall (+1 one cell off),
// -2 per echo with a known wall well before it (the beam passed there), -2 per reading with no
// echo although a known wall lies well within `reachCm`. `blocked`: a direction the robot could
// not drive in from `at`; -2 when the map holds the cell there free. A cell the map holds
// occupied cannot be stood in: the lowest possible score.
int standingScore(const network::RoomMap& known, Cell at, const std::vector<StandingReading>& readings,
                  const RangeGeometry& geometry, int reachCm, const Dir* blocked);

// The shift (dx, dy, each within +-maxShift cells) of `believed` to a cell the map holds free (the
// robot got there over free cells) with the best score, when it beats
// the unshifted cell by at least `margin` points (ties: the smaller shift); otherwise (0, 0).
Cell bestStandingShift(const network::RoomMap& known, Cell believed, const std::vector<StandingReading>& readings,
                       const RangeGeometry& geometry, int reachCm, const Dir* blocked, int maxShift = 2,
                       int margin = 2);

}  // namespace nxtmap::house
