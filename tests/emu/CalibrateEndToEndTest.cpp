// The PC's Calibrate carried out by the real firmware image in the emulated brick: a robot whose turns are 2 %
// off (nxt-uncalibrated) sweeps, turns four whole turns and sweeps again where it stands, and then tells the PC
// its turns' error within 0.5 % of what its wheels truly do, keeps it in flash, and stands where it stood.
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

TEST(CalibrateEndToEnd, TheBrickMeasuresItsTurnsWhereItStandsAndKeepsWhatItMeasured) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "two and a half emulated minutes: make test runs this from the Release build";
#endif
  const std::string elf = std::string(NXTMAP_EMU_FIRMWARE_DIR) + "/nxtmap.elf";
  if (!std::filesystem::exists(elf)) GTEST_SKIP() << "no nxtmap.elf";
  ElfLoad load = ElfImage::load(elf);
  ASSERT_TRUE(load.image) << load.error;
  const sim::WorldLoad world =
      sim::World::load(std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/occupancy-120.map");
  ASSERT_TRUE(world.world) << world.error;

  MemoryLink radio;
  EmulatedRunOptions o;
  o.brick.startCol = 6;  // walls in reach on two sides, room to turn
  o.brick.startRow = 14;
  o.brick.robot = *sim::robotByName("brick");
  o.brick.noise = *sim::noiseProfileByName("nxt-uncalibrated");
  o.brick.seed = 1;
  o.brick.link = &radio;
  o.pressEnterAtS = -1;
  o.stopWhenExplored = false;
  o.maxSeconds = 600;

  link::Session pc;
  uint32_t lastMs = 0;
  uint16_t seq = 0;
  uint64_t ackedAt = 0, countersAtRest = 0;
  bool calibrating = false, rested = false;
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
    if (pc.status()->mode == protocol::BrickMode::Exploring) calibrating = true;
    if (calibrating && !rested && pc.status()->mode == protocol::BrickMode::Idle) {
      rested = true;
      countersAtRest = pc.countersReceived();
    }
    return rested && pc.countersReceived() > countersAtRest;  // the wheels as they are after it
  };
  EmulatedRun emulated(*load.image, *world.world, o);
  const double startX = emulated.brick().robot().xCm(), startY = emulated.brick().robot().yCm();
  const EmulatedRunReport r = emulated.run();
  ASSERT_FALSE(r.fault) << r.fault.describe();
  ASSERT_TRUE(calibrating) << "the brick never reported calibrating";
  ASSERT_TRUE(rested) << "still calibrating after " << r.emulatedSeconds << " s";
  ASSERT_TRUE(pc.brickCounters().has_value());

  const double truePercent = emulated.brick().robot().wheels().systematicTurnError() * 100.0;
  const double toldPercent = pc.brickCounters()->wheelTurn10Ppm * 1e-3;
  EXPECT_GT(std::fabs(truePercent), 1.5) << "the preset's 2 % track-width error";
  EXPECT_NEAR(toldPercent, truePercent, 0.5);
  const std::optional<WheelCalibration> kept = storedWheels(emulated.brick().machine().flashContents());
  ASSERT_TRUE(kept.has_value()) << "nothing in flash";
  EXPECT_NEAR(kept->turnPpm * 1e-4, toldPercent, 0.011);
  EXPECT_LT(std::hypot(emulated.brick().robot().xCm() - startX, emulated.brick().robot().yCm() - startY), 5.0)
      << "turned on the spot";
  EXPECT_GT(r.emulatedSeconds, 60.0) << "two sweeps and four whole turns take their time";
}

}  // namespace
}  // namespace nxtmap::emu::test
