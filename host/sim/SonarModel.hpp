// SonarModel: one LEGO NXT ultrasonic sensor's raw reading in a Scene, as measured
// (nxt-sonar-and-odometry.md), with the deviations of a SonarNoise.
//
// A ping casts kRaysPerCone rays across the beam (one ray for a zero cone); each ray's hit is an echo unless
// the beam is narrower than the ray's offset at that range, the surface is out of its range or too weak, the
// sensor is turned too far from a hard face's normal (then sometimes a phantom after a second bounce), or the
// near field masks it. The first echo to return (the shortest path) is read: rangeScale * path + biasCm, plus an error fixed
// per pose, per-ping jitter and gaussian noise, rounded to whole cm (0..254, 255 = no echo).
//
// Randomness: per-ping events (dropout, cross-talk, wild values, jitter, the typical gaussian and specular
// miss) draw from the robot's generator, and only when their fields are non-zero; with `typical` the draws
// are exactly those of the published simulator. Everything that belongs to the geometry (the fixed error,
// whether a weak or oblique echo returns) is a hash of the pose (face to ~1 cm, axis to ~1 degree, sensor,
// seed): a repeat ping at the same pose agrees, and draws nothing.
#pragma once

#include "host/sim/Scene.hpp"
#include "host/sim/SonarNoise.hpp"

#include <array>
#include <cstdint>
#include <random>

namespace nxtmap::sim {

class SonarModel {
 public:
  static constexpr int kNoEcho = 255;
  static constexpr int kRaysPerCone = 9;   // rays across a cone wider than 0
  static constexpr double kPingMs = 55.0;  // firmware SonarSequencer: 50 ms echo wait + 5 ms command gap
  static constexpr int kSensors = 4;

  // reachCm: farthest echo (255). seed: the run's seed, for the per-pose part.
  SonarModel(const SonarNoise& noise, double reachCm, uint64_t seed);

  // One raw reading, whole cm 0..254 or 255 = no echo, of sensor `sensor` (0..3; any other gives 255) whose
  // face is at `face` (plane cm) pointing along compass `axisDeg`, pinged at simulated time atMs (ms);
  // othersFiring: another sensor pings at this same moment. rng is the robot's generator.
  int ping(const Scene& scene, const Vec2& face, double axisDeg, int sensor, double atMs, bool othersFiring,
           std::mt19937_64& rng);

  // The beam's half-angle for an echo at rangeCm, degrees (range-dependent when coneWideDeg > 0).
  double beamHalfAngleDeg(double rangeCm) const;
  const SonarNoise& noise() const { return noise_; }
  double reachCm() const { return reachCm_; }

 private:
  struct Echo {
    bool found = false;
    double pathCm = 0.0;   // one-way path of the sound, cm: which echo arrives first
    double valueCm = 0.0;  // what the sensor makes of it before the random parts, cm
    double incidenceDeg = 0.0;
  };
  // The pose's key: the face to ~1 cm, the axis to ~1 degree, the sensor and the seed.
  struct PoseKey {
    uint64_t hash = 0;
  };

  PoseKey keyOf(const Vec2& face, double axisDeg, int sensor) const;
  bool heardOthers(int sensor, double atMs, bool othersFiring);
  // The error fixed per pose (cm) as SonarNoise::poseErrorDraw says it is drawn.
  double poseError(const Echo& echo, int sensor, const PoseKey& key, std::mt19937_64& rng) const;
  Echo firstEcho(const Scene& scene, const Vec2& face, double axisDeg, const PoseKey& key) const;
  Echo echoOf(const Scene& scene, const Vec2& face, double axisDeg, double rayDeg, const SceneHit& hit,
              const PoseKey& key) const;
  double echoProbability(const SceneHit& hit) const;
  Echo phantom(const Scene& scene, const Vec2& face, double rayDeg, const SceneHit& hit) const;
  double linear(double pathCm) const;
  int wild(int reading, std::mt19937_64& rng) const;

  SonarNoise noise_;
  double reachCm_;
  uint64_t seed_;
  std::array<double, kSensors> lastPingMs_{};
  std::array<bool, kSensors> pinged_{};
};

}  // namespace nxtmap::sim
