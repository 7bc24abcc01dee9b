// PoseErrorShare through the simulator: how much of a run the belief spent off the truth. A robot whose wheels
// and sensor err nowhere is never off; the worse the wheels, the more of the run it is; reading the pose from
// the walls keeps it on.
#include <gtest/gtest.h>

#include <string>

#include "host/mapping/MappingRun.hpp"
#include "host/mapping/PoseErrorShare.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "tests/mapping/WorldText.hpp"

namespace nxtmap::mapping {
namespace {

// A 3.0 x 2.4 m room with a box in it, the start at (0.5, -0.5) m facing north.
sim::Site room() {
  return test::siteFromWorldText(
      "nxtmap_world: 1\noutline:\n  polygon: [[-1.5, -1.2], [1.5, -1.2], [1.5, 1.2], [-1.5, 1.2]]\n"
      "obstacles:\n  - polygon: [[-0.6, 0.2], [-0.2, 0.2], [-0.2, 0.6], [-0.6, 0.6]]\n"
      "start: {x: 0.5, y: -0.5, yaw: 90}\n");
}

PoseErrorShare shareOf(const std::string& noise, uint64_t seed, bool correct = true) {
  const sim::Site site = room();
  RunConfig c;
  c.startPose = site.start;
  c.robot = *sim::robotByName("brick");
  c.noise = *sim::noiseProfileByName(noise);
  c.seed = seed;
  c.poseCorrection = correct;
  MappingRun run(site, c);
  PoseErrorShare share;
  while (run.step()) share.add(run);
  return share;
}

TEST(PoseErrorShare, ARobotThatErrsNowhereIsNeverOff) {
  const PoseErrorShare s = shareOf("ideal", 1);
  EXPECT_GT(s.actions(), 100u);
  EXPECT_EQ(s.headingOffPct(), 0.0);
  EXPECT_EQ(s.positionOffPct(), 0.0);
}

TEST(PoseErrorShare, WorseWheelsAreOffMoreOfTheRun) {
  // Summed over seeds: single runs are chaotic.
  double typical = 0, harsh = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    typical += shareOf("typical", seed).headingOffPct();
    harsh += shareOf("harsh", seed).headingOffPct();
  }
  EXPECT_GT(harsh, typical);
  EXPECT_GT(harsh, 0.0);
}

TEST(PoseErrorShare, ARobotThatReadsItsPoseIsOffLessOfTheRunThanOneThatDoesNot) {
  double reading = 0, deadReckoning = 0;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    reading += shareOf("nxt", seed).positionOffPct();
    deadReckoning += shareOf("nxt", seed, false).positionOffPct();
  }
  EXPECT_LT(reading, deadReckoning / 2) << "with pose readings " << reading << " %, without " << deadReckoning << " %";
}

}  // namespace
}  // namespace nxtmap::mapping
