// A brick's first outing through the real firmware image in the emulated brick: told to explore (Enter) with
// nothing in flash, it knows its turns no better than an uncalibrated NXT, so before it maps it measures them
// where it stands (a sweep, four whole turns, a second sweep: PilotConfig::calibrateUnknownTurns); a brick that
// holds its wheels in flash from an earlier run sweeps square and sets off. Seen from outside, by what the
// robot's body does before it first leaves the spot: how far it turned on it, and when it left.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "host/emu/EmulatedRun.hpp"
#include "host/emu/FlashState.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::emu::test {
namespace {

#ifdef NXTMAP_EMU_FIRMWARE_DIR

constexpr double kLeftCm = 10.0;  // farther from where it was set down: it has left the spot

struct BeforeLeaving {
  double turnedDeg = 0.0;  // the body's net rotation on the spot, + clockwise
  double leftAtS = -1.0;   // when it left the spot (-1: never)
  std::string fault;
};

// A plain room of 20 cm cells, 2.0 x 1.6 m: every wall within a sweep's reach of the start.
sim::World smallRoom() {
  return sim::World::fromRows(
      {"##########", "#........#", "#........#", "#........#", "#........#", "#........#", "#........#", "##########"},
      0.20);
}

// Explore pressed at 1 s at (3, 4) of the small room under nxt-uncalibrated.
BeforeLeaving firstOuting(const ElfImage& image, const sim::World& world, uint64_t seed) {
  EmulatedRunOptions o;
  o.brick.startCol = 3;
  o.brick.startRow = 4;
  o.brick.robot = *sim::robotByName("brick");
  o.brick.noise = *sim::noiseProfileByName("nxt-uncalibrated");
  o.brick.seed = seed;
  o.stopWhenExplored = false;
  o.maxSeconds = 240;
  BeforeLeaving b;
  EmulatedRun* run = nullptr;
  double x0 = 0, y0 = 0, lastHeading = 0;
  uint64_t lastMs = 0;
  o.onEvent = [&](uint64_t cycles) {
    const uint64_t ms = cycles / (kMckHz / 1000);
    if (ms == lastMs || run == nullptr) return false;
    lastMs = ms;
    const sim::SimRobot& robot = run->brick().robot();
    b.turnedDeg += std::remainder(robot.headingDeg() - lastHeading, 360.0);
    lastHeading = robot.headingDeg();
    if (std::hypot(robot.xCm() - x0, robot.yCm() - y0) < kLeftCm) return false;
    b.leftAtS = ms / 1000.0;
    return true;
  };
  EmulatedRun emulated(image, world, o);
  run = &emulated;
  x0 = emulated.brick().robot().xCm();
  y0 = emulated.brick().robot().yCm();
  lastHeading = emulated.brick().robot().headingDeg();
  const EmulatedRunReport r = emulated.run();
  if (r.fault) b.fault = r.fault.describe();
  return b;
}

TEST(FirstOutingEndToEnd, AFreshBrickMeasuresItsTurnsBeforeItMapsAndOneThatHoldsThemDoesNot) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "eight runs of up to 90 emulated seconds: make test runs this from the Release build";
#endif
  const std::string elf = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf";
  if (!std::filesystem::exists(elf)) GTEST_SKIP() << "no nxtmap.elf";
  ElfLoad load = ElfImage::load(elf);
  ASSERT_TRUE(load.image) << load.error;
  const sim::World world = smallRoom();
  WheelCalibration held;  // what a run before learnt: turns known to 0.3 %
  held.turnPpm = 15000;
  held.turnVariance = 3000LL * 3000;
  held.driftVariance = 5000LL * 5000;
  const ElfImage calibrated = withStoredWheels(*load.image, held);

  for (uint64_t seed = 1; seed <= 4; ++seed) {
    const BeforeLeaving fresh = firstOuting(*load.image, world, seed);
    ASSERT_EQ(fresh.fault, "") << "seed " << seed;
    ASSERT_GT(fresh.leftAtS, 0.0) << "seed " << seed << ": a fresh brick never set off";
    // Four whole turns counter-clockwise between the sweeps, each sweep back where it began: about -1440 deg.
    EXPECT_LT(fresh.turnedDeg, -1300.0) << "seed " << seed << ": a fresh brick measures its turns first";
    EXPECT_GT(fresh.turnedDeg, -1600.0) << "seed " << seed;

    const BeforeLeaving kept = firstOuting(calibrated, world, seed);
    std::printf("seed %llu: fresh turned %.0f deg and left at %.1f s; with its wheels held %.0f deg, %.1f s\n",
                static_cast<unsigned long long>(seed), fresh.turnedDeg, fresh.leftAtS, kept.turnedDeg, kept.leftAtS);
    ASSERT_EQ(kept.fault, "") << "seed " << seed;
    ASSERT_GT(kept.leftAtS, 0.0) << "seed " << seed << ": a calibrated brick never set off";
    EXPECT_LT(std::fabs(kept.turnedDeg), 360.0) << "seed " << seed << ": it only squares to the walls";
    EXPECT_LT(kept.leftAtS + 20.0, fresh.leftAtS) << "seed " << seed << ": the four turns and a sweep take their time";
  }
}

#endif

}  // namespace
}  // namespace nxtmap::emu::test
