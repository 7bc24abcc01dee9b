// The NXT's wheels as the WheelModel tests set them (WheelModelTest, WheelModelUmbmarkTest): diameter and track
// in cm, and pi.
#pragma once

#include "host/sim/WheelModel.hpp"

namespace nxtmap::sim::test {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kD = kNxtWheelDiameterCm;
inline constexpr double kTrack = kNxtTrackCm;

}  // namespace nxtmap::sim::test
