// The PC's Calibrate carried out by the real firmware image in the emulated brick: a robot whose turns are 2 %
// off (nxt-uncalibrated) sweeps, turns four whole turns and sweeps again where it stands, and then tells the PC
// its turns' error, keeps it in flash, and stands where it stood. Over eight seeds (the wheels' signs and noise,
// the sonar's draws) every error it tells lies within 0.5 % of what its wheels truly do, and one it could not
// measure (no wall direction in a sweep) is told as none rather than as a wrong one. Not every seed measures:
// at this spot the first sweep finds no wall direction in 3 of the 8 at c5110fb (an open weakness of the wall
// direction under the `nxt` sonar, see issue 18's notes; at ce53bd9, with kinder emulated wheels, 6 of the 8
// measured nothing and one 0.52 % off); the test asks for at least half of them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "host/emu/EmulatedRun.hpp"
#include "host/emu/FlashState.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/link/Session.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotDescription.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::emu::test {
namespace {

struct Calibration {
  bool calibrating = false, rested = false, counters = false, kept = false;
  double truePercent = 0, toldPercent = 0, keptPercent = 0;  // the turns' error: the wheels', told, in flash
  double movedCm = 0, seconds = 0;
  std::string fault;
};

Calibration calibrate(const ElfImage& image, const sim::World& world, uint64_t seed) {
  MemoryLink radio;
  EmulatedRunOptions o;
  o.brick.startCol = 6;  // walls in reach on two sides, room to turn
  o.brick.startRow = 14;
  o.brick.robot = *sim::robotByName("brick");
  o.brick.noise = *sim::noiseProfileByName("nxt-uncalibrated");
  o.brick.seed = seed;
  o.brick.link = &radio;
  o.pressEnterAtS = -1;
  o.stopWhenExplored = false;
  o.maxSeconds = 600;

  link::Session pc;
  uint32_t lastMs = 0;
  uint16_t seq = 0;
  uint64_t ackedAt = 0, countersAtRest = 0;
  Calibration c;
  o.onEvent = [&](uint64_t cycles) {
    const auto ms = static_cast<uint32_t>(cycles / (kMckHz / 1000));
    if (ms == lastMs) return false;
    lastMs = ms;
    if (!radio.fromBrick.empty()) pc.receive(radio.fromBrick.data(), radio.fromBrick.size(), ms);
    radio.fromBrick.clear();
    const std::vector<uint8_t> sent = pc.transmit(ms);
    radio.toBrick.insert(radio.toBrick.end(), sent.begin(), sent.end());
    if (!pc.connected()) return false;
    if (seq == 0) seq = pc.calibrate();
    if (ackedAt == 0 && pc.acknowledged(seq)) ackedAt = pc.statusesReceived() + 1;
    if (ackedAt == 0 || pc.statusesReceived() <= ackedAt) return false;
    if (pc.status()->mode == protocol::BrickMode::Exploring) c.calibrating = true;
    if (c.calibrating && !c.rested && pc.status()->mode == protocol::BrickMode::Idle) {
      c.rested = true;
      countersAtRest = pc.countersReceived();
    }
    return c.rested && pc.countersReceived() > countersAtRest;  // the wheels as they are after it
  };
  EmulatedRun emulated(image, world, o);
  const double startX = emulated.brick().robot().xCm(), startY = emulated.brick().robot().yCm();
  const EmulatedRunReport r = emulated.run();
  if (r.fault) c.fault = r.fault.describe();
  c.seconds = r.emulatedSeconds;
  c.truePercent = emulated.brick().robot().wheels().systematicTurnError() * 100.0;
  c.counters = pc.brickCounters().has_value();
  if (c.counters) c.toldPercent = pc.brickCounters()->wheelTurn10Ppm * 1e-3;
  const std::optional<WheelCalibration> kept = storedWheels(emulated.brick().machine().flashContents());
  c.kept = kept.has_value();
  if (c.kept) c.keptPercent = kept->turnPpm * 1e-4;
  c.movedCm = std::hypot(emulated.brick().robot().xCm() - startX, emulated.brick().robot().yCm() - startY);
  return c;
}

TEST(CalibrateEndToEnd, TheBrickMeasuresItsTurnsWhereItStandsAndKeepsWhatItMeasured) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "eight times two and a half emulated minutes: make test runs this from the Release build";
#endif
  const std::string elf = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf";
  if (!std::filesystem::exists(elf)) GTEST_SKIP() << "no nxtmap.elf";
  ElfLoad load = ElfImage::load(elf);
  ASSERT_TRUE(load.image) << load.error;
  const sim::WorldLoad world =
      sim::World::load(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/occupancy-120.map");
  ASSERT_TRUE(world.world) << world.error;

  int measured = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    const Calibration c = calibrate(*load.image, *world.world, seed);
    ASSERT_EQ(c.fault, "") << "seed " << seed;
    ASSERT_TRUE(c.calibrating) << "seed " << seed << ": the brick never reported calibrating";
    ASSERT_TRUE(c.rested) << "seed " << seed << ": still calibrating after " << c.seconds << " s";
    ASSERT_TRUE(c.counters) << "seed " << seed;
    EXPECT_GT(std::fabs(c.truePercent), 1.5) << "the preset's 2 % track-width error";
    if (c.toldPercent != 0.0) {
      ++measured;
      EXPECT_NEAR(c.toldPercent, c.truePercent, 0.5) << "seed " << seed;
      EXPECT_GT(c.seconds, 60.0) << "seed " << seed << ": two sweeps and four whole turns take their time";
    }
    ASSERT_TRUE(c.kept) << "seed " << seed << ": nothing in flash";
    EXPECT_NEAR(c.keptPercent, c.toldPercent, 0.011) << "seed " << seed;
    EXPECT_LT(c.movedCm, 5.0) << "seed " << seed << ": turned on the spot";
  }
  EXPECT_GE(measured, 4) << "of 8 seeds";
}

}  // namespace
}  // namespace nxtmap::emu::test
