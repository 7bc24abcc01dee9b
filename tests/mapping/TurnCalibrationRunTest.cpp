// The start's turn calibration through the simulator: two sweeps with whole turns between them measure the turns'
// error (nxt-uncalibrated's track width), also after an approach, and a robot that knows nothing of its turns
// calibrates unasked.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "host/mapping/MappingRun.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/WheelModel.hpp"
#include "tests/mapping/TurnedRoom.hpp"

namespace nxtmap::mapping {
namespace {

using test::room;

// The turns' true error of the robot a run builds for `seed` (the sim's wheel model: Eb = actual track /
// nominal, every turn falls short by 1 / Eb).
double trueTurnError(const sim::NoiseProfile& noise, uint64_t seed) {
  const sim::WheelModel wheels(noise.wheels, 5.6, 11.2, seed);
  return 11.2 / wheels.trackCm() - 1.0;
}

// The turn calibration of the robot a run builds for `seed` under nxt-uncalibrated (set down 10 degrees off square
// at the start of `site`), run until the explorer starts: found, measured and true turn error.
struct Calibrated {
  bool found = false;
  double measured = 0.0, truth = 0.0;
  int32_t correctingPpm = 0;  // what the pilot corrects every turn by from then on
};
Calibrated calibrateAt(const sim::Site& site, uint64_t seed) {
  RunConfig c;
  c.startPose = site.start;
  c.startJitterDeg = 10;
  c.noise = *sim::noiseProfileByName("nxt-uncalibrated");
  c.seed = seed;
  c.calibrateTurns = 4;
  MappingRun run(site, c);
  for (int i = 0; i < 5000 && !run.pilot().explorerStarted(); ++i) run.step();
  EXPECT_TRUE(run.pilot().explorerStarted());
  const TurnCalibration& cal = run.pilot().calibration();
  return Calibrated{cal.found(), cal.errorPpm() / 1e6, trueTurnError(c.noise, seed), run.pilot().turnErrorPpm()};
}

TEST(StartSquaringRun, TheTurnCalibrationRecoversAKnownTrackWidthError) {
  const sim::Site site = room(10);
  int positive = 0;
  // Measured over seeds 1-30: |measured - true| mean 0.18 %, worst 0.48 %.
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const Calibrated k = calibrateAt(site, seed);
    ASSERT_TRUE(k.found) << "seed " << seed;
    EXPECT_GT(std::fabs(k.truth), 0.015) << "nxt-uncalibrated: a 2 % track-width error";
    EXPECT_NEAR(k.measured, k.truth, 0.005) << "seed " << seed;
    EXPECT_EQ(k.correctingPpm, std::lround(k.measured * 1e6));
    if (k.truth > 0) ++positive;
  }
  EXPECT_GT(positive, 0);  // both signs among the seeds
  EXPECT_LT(positive, 10);
}

TEST(StartSquaringRun, ACalibrationWhoseFirstSweepSawNoWallMeasuresAfterTheApproach) {
  // The 4.4 m room turned 13 degrees, the robot in its middle: its walls 2.2 m away, beyond what a sweep finds
  // walls within. The calibration's first sweep finds none; the robot approaches an echo and calibrates there (it
  // used to square there and leave the turns unmeasured).
  const sim::Site site = room(13, 4.4, 4.4, 0.0, 0.0);
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const Calibrated k = calibrateAt(site, seed);
    ASSERT_TRUE(k.found) << "seed " << seed;
    EXPECT_NEAR(k.measured, k.truth, 0.005) << "seed " << seed;
  }
}

// Whether a run calibrates its turns unasked (PilotConfig::calibrateUnknownTurns): only a robot that sweeps and knows
// its turns no better than an uncalibrated NXT; what it measures is right, and it is what the pilot corrects by.
TEST(StartSquaringRun, ARobotThatKnowsNothingOfItsTurnsCalibratesUnasked) {
  const sim::Site site = room(10);
  WheelCalibration known;
  known.turnVariance = 5000LL * 5000;  // 0.5 %: a calibrated robot's (what a run before learnt)
  struct Row {
    const char* what;
    const char* noise;
    bool square, whenUnknown;
    std::optional<WheelCalibration> stored;
    bool calibrates;
  };
  const Row rows[] = {
      {"nothing known of the turns", "nxt-uncalibrated", true, true, std::nullopt, true},
      {"the same, told never to", "nxt-uncalibrated", true, false, std::nullopt, false},
      {"no sweep (it keeps the frame it was set down in)", "nxt-uncalibrated", false, true, std::nullopt, false},
      {"turns known from a run before", "nxt-uncalibrated", true, true, known, false},
      {"a calibrated robot (nxt: turns known to 0.5 %)", "nxt", true, true, std::nullopt, false},
      {"an uncalibrated robot's defaults stored", "nxt", true, true, WheelCalibration{}, true},
  };
  for (const Row& r : rows) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
      RunConfig c;
      c.startPose = site.start;
      c.startJitterDeg = 10;
      c.noise = *sim::noiseProfileByName(r.noise);
      c.seed = seed;
      c.squareAtStart = r.square;
      c.calibrateUnknownTurns = r.whenUnknown;
      c.storedWheels = r.stored;
      MappingRun run(site, c);
      for (int i = 0; i < 5000 && !run.pilot().explorerStarted(); ++i) run.step();
      ASSERT_TRUE(run.pilot().explorerStarted()) << r.what;
      const TurnCalibration& cal = run.pilot().calibration();
      EXPECT_EQ(cal.turns() > 0, r.calibrates) << r.what << ", seed " << seed;
      EXPECT_EQ(cal.found(), r.calibrates) << r.what << ", seed " << seed;
      if (!r.calibrates) continue;
      EXPECT_NEAR(cal.errorPpm() / 1e6, trueTurnError(c.noise, seed), 0.005) << r.what << ", seed " << seed;
      EXPECT_EQ(run.pilot().turnErrorPpm(), cal.errorPpm() + (r.stored ? r.stored->turnPpm : 0)) << r.what;
    }
  }
}

}  // namespace
}  // namespace nxtmap::mapping
