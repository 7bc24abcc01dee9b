// PoseErrorShare: how much of a mapping run the robot spent with its belief off the truth, counted after every
// action once the explorer has started (the start's sweep is not counted: the frame is laid there). A figure of
// the localisation itself, steadier than the maps' scores, in which a run turns on a few moments: the share of
// actions with the heading more than kHeadingMrad off, and with the centre more than a quarter of a cell off
// the believed one.
#pragma once

#include <cstdint>

namespace nxtmap::mapping {

class MappingRun;

class PoseErrorShare {
 public:
  static constexpr double kHeadingMrad = 40.0;  // 2.3 deg: over a 1 m run, 4 cm (a fifth of the brick's cell) aside

  // The run as it stands after an action.
  void add(const MappingRun& run);
  uint64_t actions() const { return actions_; }
  // Percentages of the counted actions (0 when none were counted).
  double headingOffPct() const { return pct(headingOff_); }
  double positionOffPct() const { return pct(positionOff_); }

 private:
  double pct(uint64_t n) const { return actions_ == 0 ? 0.0 : 100.0 * static_cast<double>(n) / actions_; }
  uint64_t actions_ = 0, headingOff_ = 0, positionOff_ = 0;
};

}  // namespace nxtmap::mapping
