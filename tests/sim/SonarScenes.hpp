// The scenes and the sensor the SonarModel tests measure it in (SonarModelTest, SonarPoseErrorTest).
#pragma once

#include <cstdint>
#include <random>

#include "host/sim/SonarModel.hpp"

namespace nxtmap::sim::test {

inline constexpr double kReach = 255.0;  // cm: the farthest echo (SonarModel's reach)

// The measured sensor without its wild readings (tested on their own): jasonatwood's fit is of mean readings.
inline SonarNoise nxtClean() {
  SonarNoise s = sonarPreset("nxt");
  s.wildProb = 0.0;
  return s;
}

// A room whose walls lie beyond the sensor's reach, holding what the test adds.
inline Scene openRoom() {
  Scene scene;
  scene.addRing(Ring{{Vec2(-1000, -1000), Vec2(1000, -1000), Vec2(1000, 1000), Vec2(-1000, 1000)}, Surface::Hard});
  return scene;
}

// A long straight target along y = 0 (a face at (x, d) pointing north is d cm from it).
inline Scene flatWall(Surface surface) {
  Scene scene = openRoom();
  scene.addWall(Edge{Vec2(-800, 0), Vec2(800, 0), surface});
  scene.finish();
  return scene;
}

// One ping of sensor 0 at (x, d) turned turnDeg from the wall's normal, with a fresh model (no cross-talk
// state) of the run's seed; rng is the robot's generator, shared by the poses of a test.
inline int pingWall(const Scene& scene, const SonarNoise& noise, double x, double d, double turnDeg, uint64_t seed,
                    std::mt19937_64& rng) {
  SonarModel model(noise, kReach, seed);
  return model.ping(scene, Vec2(x, d), turnDeg, 0, 0.0, false, rng);
}

}  // namespace nxtmap::sim::test
