#pragma once

#include "common/motion/PoseTracker.hpp"

namespace nxtmap::fw {

// WheelStore: where the brick keeps what it learnt of its wheels while it is switched off (ModeMachine loads
// it at start-up and saves it when a run ends or is stopped). On the brick a page of its flash
// (FlashWheelStore); in the host tests a plain variable. Not in the RAM-run image (it learns no wheels).
class WheelStore {
 public:
  // True, and `w` set, when something is stored; else `w` is left as it was.
  virtual bool load(WheelCalibration& w) const = 0;
  // Keeps `w` (nothing is written when it is what is kept already). False: it could not be kept.
  virtual bool save(const WheelCalibration& w) = 0;

 protected:
  WheelStore() = default;
  ~WheelStore() = default;
};

}  // namespace nxtmap::fw
