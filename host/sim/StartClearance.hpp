// StartClearance: where a person sets down a robot whose body sweeps out of its cell when it turns. The
// robot's instructions say "set it down with room to turn: nothing within a cell and a half ahead, behind
// or to either side" (the explorer turns only where the four cells around it are free,
// ExplorerConfig::turnNeedsRoom); a start that leaves no room (a corner cell beside two walls) is moved by
// whole cells to the nearest spot that does, as the person would.
#pragma once

#include "host/sim/Scene.hpp"
#include "host/sim/Site.hpp"

namespace nxtmap::sim {

struct ClearStart {
  StartPose pose;        // the start with room to turn (the given one when it has room or none is found)
  double movedCm = 0.0;  // how far it was moved: 0 when it had room, < 0 when no spot within reach has any
};

// Whether a robot at `pose` has room to turn: a disc of sweepCm around it and the four cells of cellCm
// beside its own (on its grid, laid square to its heading) are clear of every obstacle of the scene.
bool roomToTurnAt(const Scene& scene, const StartPose& pose, double cellCm, double sweepCm);

// The start moved by whole cells (cellCm, along the plane's axes, at most kReachCells either way: 1.6 m on the
// brick, as far as a person looks for room around a cluttered corner) to the nearest spot with room to turn
// that is reachable from it in a straight line or by steps of a cell round obstacles (never through a wall);
// the heading kept.
constexpr int kReachCells = 8;
ClearStart withRoomToTurn(const Scene& scene, const StartPose& start, double cellCm, double sweepCm);

}  // namespace nxtmap::sim
