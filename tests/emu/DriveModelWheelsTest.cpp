// DriveModel with the robot's WheelModel: the tacho probe spins the robot on the spot (motor A = left
// forward, B = right backward, 50 % for 0.5 s) under one wheel error at a time. The encoders count motor
// degrees whatever the wheels do; the ground motion shows Eb, Ed and backlash by the stated amounts.
#include "EmuTestSupport.hpp"

#include <cmath>

namespace nxtmap::emu::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Spin {
  double headingDeg;             // the robot's heading after the probe (started at 0 = N)
  double drivenCm;               // distance the centre moved
  std::vector<uint32_t> counts;  // the probe's encoder counts A, B, C
  double leftMotorDeg;
  double trackRatio;     // the robot's Eb
  double diameterRatio;  // the robot's Ed
};

Spin spinWith(const sim::WheelNoise& wheels, uint64_t seed) {
  BrickConfig c;
  c.startCol = 5;
  c.startRow = 6;
  c.noise.wheels = wheels;
  c.seed = seed;
  ProbeRun r("tacho", c, 3.0);
  EXPECT_TRUE(r.ok) << r.fault();
  sim::SimRobot& robot = r.brick->robot();
  return Spin{robot.headingDeg(),           r.brick->drive().drivenCm(), r.port().values,
              r.brick->drive().wheelDeg(0), robot.wheels().trackRatio(), robot.wheels().diameterRatio()};
}

// Without wheel errors the seed changes nothing: one run serves every comparison.
const Spin& cleanSpin() {
  static const Spin clean = spinWith(sim::WheelNoise{}, 1);
  return clean;
}

// The wheels' nominal arc per motor degree and the heading a wheel-degree difference makes.
double cmPerDeg() { return kPi * sim::kNxtWheelDiameterCm / 360.0; }
double headingPerWheelDeg() { return cmPerDeg() / sim::kNxtTrackCm * 180.0 / kPi; }

struct WheelCase {
  const char* what;
  double trackError, diameterRatioError, backlashDeg;
};
class DriveModelWheels : public ::testing::TestWithParam<WheelCase> {};

TEST_P(DriveModelWheels, EncodersCountMotorDegreesAndTheGroundShowsTheError) {
  const WheelCase w = GetParam();
  sim::WheelNoise noise;
  noise.trackError = w.trackError;
  noise.diameterRatioError = w.diameterRatioError;
  noise.backlashDeg = w.backlashDeg;
  for (uint64_t seed : {1u, 2u}) {
    const Spin& clean = cleanSpin();
    const Spin s = spinWith(noise, seed);
    ASSERT_GT(clean.headingDeg, 60.0);  // a clockwise spin of about 100 degrees
    EXPECT_EQ(s.counts, clean.counts) << w.what << ", seed " << seed;
    EXPECT_EQ(s.leftMotorDeg, clean.leftMotorDeg);
    EXPECT_NEAR(std::abs(s.trackRatio - 1.0), w.trackError, 1e-12);
    // Eb: every turn scaled by 1 / Eb. Backlash: the right wheel reverses from its forward-engaged
    // start and loses the play while the left one rolls alone. Ed: the larger wheel pushes the
    // centre by half the arcs' difference.
    const double expectedHeading = (clean.headingDeg - w.backlashDeg * headingPerWheelDeg()) / s.trackRatio;
    EXPECT_NEAR(s.headingDeg, expectedHeading, 1e-6) << w.what << ", seed " << seed;
    const double arcCm = s.leftMotorDeg * cmPerDeg();
    EXPECT_NEAR(s.drivenCm, (w.diameterRatioError * arcCm + w.backlashDeg * cmPerDeg()) / 2.0, 1e-6)
        << w.what << ", seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(
    OneErrorAtATime, DriveModelWheels,
    ::testing::Values(WheelCase{"none", 0.0, 0.0, 0.0}, WheelCase{"Eb 2 %", 0.02, 0.0, 0.0},
                      WheelCase{"Eb 0.5 %", 0.005, 0.0, 0.0},
                      WheelCase{"Ed 2 deg/m", 0.0, sim::diameterRatioErrorForDrift(2.0, 11.2), 0.0},
                      WheelCase{"backlash 2", 0.0, 0.0, 2.0}, WheelCase{"backlash 4", 0.0, 0.0, 4.0}));

TEST(DriveModelWheels, TheSignOfEbIsTheRobotsAndFollowsTheSeed) {
  sim::WheelNoise noise;
  noise.trackError = 0.02;
  int under = 0, over = 0;
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const Spin& clean = cleanSpin();
    const Spin s = spinWith(noise, seed);
    (s.headingDeg < clean.headingDeg ? under : over) += 1;
    EXPECT_EQ(s.headingDeg<clean.headingDeg, s.trackRatio> 1.0) << "seed " << seed;
  }
  EXPECT_GT(under, 0);
  EXPECT_GT(over, 0);
}

TEST(DriveModelWheels, TheNxtPresetKeepsTheCountsAndMovesTheGroundDifferently) {
  const Spin& clean = cleanSpin();
  const Spin nxt = spinWith(sim::wheelPreset("nxt-uncalibrated"), 7);
  EXPECT_EQ(nxt.counts, clean.counts);
  EXPECT_GT(std::abs(nxt.headingDeg - clean.headingDeg), 0.01);
  EXPECT_EQ(spinWith(sim::wheelPreset("nxt-uncalibrated"), 7).headingDeg, nxt.headingDeg);
}

}  // namespace
}  // namespace nxtmap::emu::test
