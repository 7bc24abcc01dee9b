// NoiseProfile: a named preset of how the simulated sonar and wheels deviate from the truth.
#pragma once

#include "host/sim/SonarNoise.hpp"
#include "host/sim/WheelNoise.hpp"

#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

struct NoiseProfile {
  std::string name;
  SonarNoise sonar;
  WheelNoise wheels;
};

// Presets, mildest first:
//   ideal            no error at all ("none" is accepted for it: the name older runs used)
//   typical          the model the published figures were measured with (kept so they reproduce)
//   nxt              the NXT sensor and drive as measured, a calibrated robot
//   nxt-uncalibrated the same with UMBmark magnitudes of an uncalibrated robot
//   harsh            worse than any sensor we know of
// nullopt for any other name.
std::optional<NoiseProfile> noiseProfileByName(const std::string& name);
std::vector<std::string> noiseProfileNames();
// Every preset's values with units, for `--noise list`.
std::string describeNoiseProfiles();

}  // namespace nxtmap::sim
