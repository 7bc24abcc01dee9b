// The pilot when the body meets something on a quarter turn (the wheels stall and the encoders count what was
// turned): the turn is finished by a three-point turn where that can help, or given up (turned back, and the
// explorer hears that its way is blocked). The RAM-run image has no room for either: there a stalled turn is
// taken as done, as the encoders counted it.
#include "common/math/IntAbs.hpp"
#include "common/math/IntTrig.hpp"
#include "common/motion/Pilot.hpp"

namespace nxtmap {

#ifndef NXTMAP_NO_START_SQUARING
DriveAction Pilot::turnStalled(const DriveEvent& e) {
  // Which way to drive out: turning clockwise the rear corners swing to the left and the front ones to the right
  // (anticlockwise the other way round), and driving forward at the partial heading moves the robot away from the
  // left. Backward only when the map shows the rear's side free and the front's not.
  const Dir h = explorer_.pose().heading;
  const int cw = e.achieved > 0 ? 1 : -1;
  const MapLayers& map = explorer_.map();
  const bool rearFree = map.at(advance(explorer_.pose().cell, rotate(h, -cw))) == CellState::Free;
  const bool frontFree = map.at(advance(explorer_.pose().cell, rotate(h, cw))) == CellState::Free;
  const DriveAction out =
      threePoint_.begin(e.achieved, commandMrad_ - e.achieved, rearFree && !frontFree ? -1 : 1, tracker_.along(h));
  if (out.kind == DriveAction::Kind::Done) return giveUpTurn();
  phase_ = Phase::ThreePoint;
  return out;
}

DriveAction Pilot::threePoint(const DriveEvent& e) {
  int32_t droveMm = 0;
  const DriveAction next = threePoint_.step(e, config_.turnStallMrad, droveMm);
  if (droveMm != 0) droveTurned(droveMm, threePoint_.partialMrad());
  if (next.kind != DriveAction::Kind::Done) return next;
  return threePoint_.made() ? turnMade(threePoint_.partialMrad()) : giveUpTurn();
}

void Pilot::droveTurned(int32_t mm, int32_t offMrad) {
  // Along the axis heading by mm cos(off), and across it, towards the side the robot turned to, by mm sin|off|.
  const Dir h = explorer_.pose().heading;
  tracker_.drove(mm * cosPerMille(offMrad) / 1000, h);
  tracker_.drove(mm * sinPerMille(abs32(offMrad)) / 1000, rotate(h, offMrad > 0 ? 1 : -1));
  readHere_ = 0;  // the readings taken here are from elsewhere now
}

DriveAction Pilot::giveUpTurn() {
  // Undo the quarter's bookkeeping and turn back to the heading the explorer holds.
  turnedUrad_ -= static_cast<int64_t>(pending_.amount / 2) * 1570796;
  commandedUrad_ -= static_cast<int64_t>(quarterMrad_) * 1000;
  phase_ = Phase::TurnBack;
  return DriveAction::rotate(-threePoint_.partialMrad());
}

DriveAction Pilot::turnedBack(const DriveEvent& e) {
  // Net of the two rotations (small unless the way back stalled too) on the heading the explorer holds.
  const int32_t stalled = threePoint_.partialMrad();
  tracker_.rotated(stalled + (e.measured ? e.achieved : -stalled), 0);
  return begin(explorer_.step(Event::turnBlocked()));
}
#endif

}  // namespace nxtmap
