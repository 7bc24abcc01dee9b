// RoomRegistration: a new room's frame comes from the robot's believed pose at the entrance, which
// drifts from room to room. The new room's map overlaps the rooms already mapped (what it saw through
// the doorway, the walls they share): the whole-cell shift of its frame, up to maxShift cells each
// way, under which the two agree best corrects the frame. Walls weigh more than free cells; a shift
// is taken only when it beats staying put by `margin`: some 16 wall cells' worth, so no overlap means
// no change and a few cells about a doorway cannot move a room (seen a cell off, they often fit a
// shift by chance). Nor is a shift taken that does not resolve kResolvedConflicts cells the two hold
// one free and one occupied: a wall both rooms share, mapped a cell apart from its two sides (a wall
// on a cell boundary), fits better laid onto itself, but nothing disagrees where the room is.
#pragma once

#include "host/network/RoomMap.hpp"
#include "host/network/RoomTransform.hpp"

namespace nxtmap::house {

constexpr int kResolvedConflicts = 4;  // cells held free by one map and occupied by the other

struct RoomRegistration {
  network::RoomTransform toHouse;  // the corrected frame (the given one when not shifted)
  int dx = 0, dy = 0;              // the shift taken, house cells
  int scoreBefore = 0, scoreAfter = 0;
  bool shifted() const { return dx != 0 || dy != 0; }
};

// fresh: the new room's map in its frame; toHouse: its frame as believed; known: the rooms already
// mapped, merged in the house frame.
RoomRegistration registerRoom(const network::RoomMap& fresh, const network::RoomTransform& toHouse,
                              const network::RoomMap& known, int maxShift, int margin = 48,
                              int resolved = kResolvedConflicts);

}  // namespace nxtmap::house
