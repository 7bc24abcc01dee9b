#pragma once
#include <cstdint>

#include "common/explore/ExplorerConfig.hpp"
#include "firmware/drivers/MotionGeometry.hpp"

namespace nxtmap::fw {

// The robot as built: which port holds what, and its dimensions. One place to change.
struct BrickConfig {
  // Sensor port (0 = port 1) of each Sensor (Front, Right, Back, Left).
  uint8_t sensorPorts[4] = {0, 1, 2, 3};
  // Output (0 = A) of each wheel; positive power drives forward.
  uint8_t leftMotor = 0;
  uint8_t rightMotor = 1;
  MotionGeometry drive{};  // 56 mm wheels, 112 mm track, 200 mm cells

  ExplorerConfig explorer() const {
    ExplorerConfig c;
    c.geometry.cellCm = static_cast<int16_t>(drive.cellMm / 10);
    c.geometry.minCm = 7;     // the LEGO sensor is unreliable closer than this
    c.geometry.maxCm = 120;   // and beyond this
    c.geometry.mountCm = 6;   // sensor faces ahead of the robot's centre
    return c;
  }
};

}  // namespace nxtmap::fw
