// The turned rectangular room the start's runs are set down in (StartSquaringRunTest, TurnCalibrationRunTest).
#pragma once

#include <string>

#include "host/sim/Site.hpp"
#include "tests/mapping/WorldText.hpp"

namespace nxtmap::mapping::test {

// A w x h m room turned `turnDeg` about the origin, the robot's start at `x, y` m facing north.
inline sim::Site room(double turnDeg, double w = 3.0, double h = 2.4, double x = 0.2, double y = -0.1) {
  const std::string text = "nxtmap_world: 1\noutline:\n  polygon: [[" + std::to_string(-w / 2) + ", " +
                           std::to_string(-h / 2) + "], [" + std::to_string(w / 2) + ", " + std::to_string(-h / 2) +
                           "], [" + std::to_string(w / 2) + ", " + std::to_string(h / 2) + "], [" +
                           std::to_string(-w / 2) + ", " + std::to_string(h / 2) +
                           "]]\nstart: {x: " + std::to_string(x) + ", y: " + std::to_string(y) +
                           ", yaw: 90}\ntransform: {rotate_deg: " + std::to_string(turnDeg) + "}\n";
  return test::siteFromWorldText(text);
}

}  // namespace nxtmap::mapping::test
