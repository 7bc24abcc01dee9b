// NoiseProfile: how the simulated ultrasonic sensors and wheels deviate from the truth.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace nxtmap::sim {

struct NoiseProfile {
    std::string name;
    double rangeSigmaCm = 0.0;      // gaussian range noise, cm (>= 0)
    double biasCm = 0.0;            // added to every echo, cm
    double dropoutProb = 0.0;       // 0..1: 255 instead of an echo
    double specularMissProb = 0.0;  // 0..1: 255 when the incidence exceeds specularAngleDeg
    double specularAngleDeg = 0.0;  // 0..90, angle between the ray and the hit face's normal
    double crosstalkProb = 0.0;     // 0..1: a bogus short echo, only when other sensors fire together
    double coneHalfAngleDeg = 0.0;  // 0 = a single ray along the sensor axis
    double slipSigma = 0.0;         // relative distance error per move (0.02 = 2 %)
    double turnSigmaDeg = 0.0;      // gaussian turn error per turn, degrees
};

// Presets "none", "typical", "harsh"; nullopt for any other name.
std::optional<NoiseProfile> noiseProfileByName(const std::string& name);

// The preset names, mildest first.
std::vector<std::string> noiseProfileNames();

}  // namespace nxtmap::sim
