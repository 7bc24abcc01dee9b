// StartAnchor: the only readings taken where the robot surely is are those at the very start. The
// start room's map is built from a pose that drifts; when the drift passed half a cell somewhere
// the robot had no wall to hold on to (a wide room), the rest of the room is mapped a whole cell
// off, consistently, and no later reading in that room can tell. The start readings can: matched
// against the finished map, the whole-cell shift of the start cell under which every one of them
// fits again is how far the map (and the belief with it) has moved.
#pragma once

#include <vector>

#include "common/grid/Cell.hpp"
#include "host/network/RoomMap.hpp"

namespace nxtmap::house {

// One echo read at the start: along `dir`, `mm` from the robot's centre to the obstacle's face.
struct AnchorReading {
  Dir dir = Dir::North;
  int mm = 0;
};

struct AnchorGeometry {
  int cellMm = 100;      // cell edge
  int reachCells = 25;   // how far along a beam a wall is looked for
  int wideFromMm = 570;  // an echo farther than this may come from the lanes beside the axis (the cone)
  int toleranceMm = 30;  // a reading fits a wall face this close to it
  int maxShift = 2;      // cells, each axis
};

// The shift (each axis within +-maxShift cells) of `start` onto a cell `map` holds free under which
// every reading along that axis meets the nearest wall face in its beam within the tolerance, where
// it does not at `start` itself; 0 on an axis with no reading, where the readings fit already, or
// where more than one shift would fit (and (0, 0) when the shifted cell is not free).
Cell startAnchorShift(const network::RoomMap& map, Cell start, const std::vector<AnchorReading>& readings,
                      const AnchorGeometry& geometry);

}  // namespace nxtmap::house
