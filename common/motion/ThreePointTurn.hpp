#pragma once
#include <cstdint>

#include "common/math/IntSqrt.hpp"
#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"

namespace nxtmap {

// ThreePointTurn: a quarter turn that stalled part way (a corner of the body met a wall: in a 20 cm cell the
// corners sweep 12 cm from the centre, the walls beside it may be 10 cm away) is finished by driving out along the
// heading it got to, far enough for the corners to clear (their reach, the half diagonal, less what they reach now,
// over the sideways share of the drive), and turning the rest. If the rest stalls as well the robot turns back to
// the partial heading and drives back in, and the turn is given up. Owned by the Pilot, which keeps the tracker:
// each step says what the robot drove (at partialMrad() off the axis heading), and once over how far it stands
// turned. Integer only; 8 bytes (the RAM budget of the simulator's firmware image has none to spare).
class ThreePointTurn {
 public:
  // The brick's body: 16 cm along the heading by 18 across, centred on the turning point (a point robot never
  // stalls), and the room its corners are given (mm).
  static constexpr int32_t kHalfLengthMm = 80, kHalfWidthMm = 90, kMarginMm = 5;
  static constexpr int32_t kReachMm = 120;  // the half diagonal
  static_assert(isqrt(kHalfLengthMm * kHalfLengthMm + kHalfWidthMm * kHalfWidthMm) == kReachMm, "the half diagonal");
  static constexpr int32_t kMaxOutMm = 110;  // the drive out is at most this long (a little over half a 20 cm cell)
  // and leaves the robot no farther off its cell's centre than this along the heading it turned from: the explorer
  // holds it in that cell (half a cell, 100 mm, less room for the tracker's error). On the brick rooms (nxt, seeds
  // 1-100) 50-85 mm mapped alike; with no limit (110) 3 and 14 more runs of 1,800 were lost.
  static constexpr int32_t kMaxOffsetMm = 70;
  // A turn that stalled before kMinStalledMrad is turned back at once (the drive would have to be long for the
  // little it moves sideways), and so is one that stalled after kMaxStalledMrad (it is nearly as turned as it gets).
  static constexpr int32_t kMinStalledMrad = 150, kMaxStalledMrad = 1200;

  // How far to drive out after a stall at stalledMrad (mm, > 0; 0: not worth trying, turn back at once).
  static int32_t outMm(int32_t stalledMrad);

  // The turn stalled at stalledMrad of the wanted restMrad + stalledMrad (both signed, + clockwise) with the robot
  // offsetMm ahead of its cell's centre (along the heading it turned from); the drive out goes forward (direction
  // +1) or backward (-1), no farther than keeps the robot within kMaxOffsetMm of the centre along that heading.
  // Returns the first action, or Done when not worth trying (given up: partialMrad() is stalledMrad).
  DriveAction begin(int32_t stalledMrad, int32_t restMrad, int direction, int32_t offsetMm);
  // The answer to the last action (a rotation stalls when it ends more than stallMrad short); droveMm gets how far
  // the robot drove (mm, signed) at partialMrad() off the axis heading, 0 when it did not. Returns the next action,
  // or Done when the turn is over: made() or given up.
  DriveAction step(const DriveEvent& e, int32_t stallMrad, int32_t& droveMm);
  bool made() const { return stage_ == Stage::Made; }
  // How far the robot stands turned from the axis heading (mrad, encoders): once made, the whole turn.
  int32_t partialMrad() const { return partialMrad_; }

 private:
  enum class Stage : uint8_t { Out, Rest, Back, In, Made, GivenUp };
  Stage stage_ = Stage::GivenUp;
  int16_t partialMrad_ = 0;
  int16_t restMrad_ = 0;   // Stage::Rest: what was asked to finish the turn; Stage::Back: to turn back
  int16_t outDoneMm_ = 0;  // the drive out as made (mm, signed)
};

}  // namespace nxtmap
