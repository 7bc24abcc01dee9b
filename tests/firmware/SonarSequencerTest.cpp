#include <gtest/gtest.h>

#include <string>

#include "firmware/drivers/SonarSequencer.hpp"
#include "tests/firmware/I2cSlaveModel.hpp"

namespace nxtmap::fw::test {
namespace {

// Runs the sequencer with 1 ms steps and the I2C engine at 28.8 ticks per ms (as the TC0 rate).
struct Rig {
  SoftI2c i2c;
  SonarSequencer sonar{i2c};
  I2cSlaveModel sensor{0x01};
  uint32_t now = 0;
  std::vector<std::pair<uint32_t, uint8_t>> commandsAt;  // (ms, value written to 0x41)
  void ms(uint32_t n) {
    for (uint32_t i = 0; i < n; ++i, ++now) {
      sonar.poll(now);
      for (int t = 0; t < 29; ++t) i2c.tick(sensor);
      while (commandsAt.size() < sensor.registerWrites.size())
        commandsAt.emplace_back(now, sensor.registerWrites[commandsAt.size()].second);
    }
  }
  uint8_t sample(uint8_t port, uint32_t limitMs = 1000) {
    EXPECT_TRUE(sonar.request(port));
    for (uint32_t i = 0; i < limitMs && !sonar.ready(); ++i) ms(1);
    EXPECT_TRUE(sonar.ready());
    return sonar.take();
  }
};

TEST(SonarSequencer, SingleShotPingThenReadsTheFirstEchoAfter50Ms) {
  Rig r;
  r.sonar.powered(0);
  r.sensor.regs[0x42] = 123;
  const uint32_t start = r.now;
  EXPECT_EQ(r.sample(2), 123);
  ASSERT_EQ(r.sensor.registerWrites.size(), 1u);
  EXPECT_EQ(r.sensor.registerWrites[0], std::make_pair(uint8_t{0x41}, uint8_t{0x01}));
  EXPECT_GE(r.commandsAt[0].first, start + SonarSequencer::kWarmupMs);  // no command during warm-up
  // The read came at least 50 ms after the ping.
  EXPECT_GE(r.now - r.commandsAt[0].first, SonarSequencer::kEchoMs);
  EXPECT_EQ(r.sonar.port(), 2);
  EXPECT_EQ(r.sonar.errors(), 0u);
}

TEST(SonarSequencer, BackToBackSamplesKeepTheCommandGap) {
  Rig r;
  r.sonar.powered(0);
  r.ms(200);
  r.sensor.regs[0x42] = 40;
  r.sample(0);
  const uint32_t readEnd = r.now;
  r.sample(0);
  // The second ping is at least kCommandGapMs after the first read finished.
  ASSERT_EQ(r.commandsAt.size(), 2u);
  EXPECT_GE(r.commandsAt[1].first + 1, readEnd + SonarSequencer::kCommandGapMs);
}

TEST(SonarSequencer, OneSensorAtATime) {
  Rig r;
  r.sonar.powered(0);
  EXPECT_TRUE(r.sonar.request(1));
  EXPECT_FALSE(r.sonar.request(3));
  EXPECT_TRUE(r.sonar.busy());
}

TEST(SonarSequencer, AMissingSensorReadsAsNoEchoAndCountsAnError) {
  Rig r;
  r.sonar.powered(0);
  r.sensor.present = false;
  EXPECT_EQ(r.sample(1), SonarSequencer::kNoEcho);
  EXPECT_EQ(r.sonar.errors(), 1u);
  EXPECT_FALSE(r.sonar.busy());
}

}  // namespace
}  // namespace nxtmap::fw::test
