#pragma once
#include <cstdint>

#include "common/sensing/RangeGeometry.hpp"

namespace nxtmap {

// Tuning of the explorers. Defaults are the published experiments' (10 cm cells, 5 cm - 1 m).
struct ExplorerConfig {
  RangeGeometry geometry{};
  int16_t minWallCells = 4;     // more consecutive occupied cells beside a deviation = a wall
  int16_t bigAreaCells = 12;    // unknown cells seen from a spot that make it a "large area"
  int16_t gainPerCostUnit = 0;  // frontier: unknown cells worth one unit of travel time
  uint32_t maxActions = 20000;  // safety stop: a run never takes more actions than this
  // Travel searches run in slices of this many search states per step (answering Action::think
  // in between), so one step stays within the brick's CPU budget (1 ms at 48 MHz).
  uint16_t searchSliceStates = 8;
  // The robot's body reaches into the four neighbouring cells when it turns on the spot (a 16 x 18 cm
  // body sweeps 12 cm from its centre; a 20 cm cell leaves 10): it turns only in a cell whose four
  // neighbours are known free, and drives along its axis (forward or backward) elsewhere. false: a
  // body that turns inside its own cell (the published point robot). Such a body that has turned a quarter
  // without meeting anything has also shown the near part of the neighbouring cells clear, as far as the
  // sensor's blind zone reaches (RangeGeometry::blindCm: the brick's 6 cm mount + 7 cm reach 3 cm into them,
  // the body 2 cm; in the last centimetre the LEGO sensor mostly answers, docs/nxt-sonar-and-odometry.md):
  // a "no echo" read there is trusted, and before a run ends the robot turns where one was not.
  bool turnNeedsRoom = false;
};

}  // namespace nxtmap
