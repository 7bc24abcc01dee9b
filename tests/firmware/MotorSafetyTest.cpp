#include <gtest/gtest.h>

#include "firmware/drivers/MotorSafety.hpp"

namespace nxtmap::fw {
namespace {

AvrCommand driving() {
  AvrCommand c;
  c.pwm[0] = 60;
  c.pwm[1] = -60;
  c.pwm[2] = 30;
  c.brakeMask = 0;
  c.inputPower = 0xF0;
  return c;
}

TEST(MotorSafety, ALiveControlLoopLeavesTheCommandAlone) {
  MotorSafety s;
  AvrCommand c = driving();
  for (uint32_t t = 0; t < 1000; ++t) {
    s.feed(t);
    EXPECT_FALSE(s.enforce(c, t));
  }
  EXPECT_EQ(c.pwm[0], 60);
  EXPECT_EQ(c.brakeMask, 0);
}

TEST(MotorSafety, SilenceOfTheControlLoopStopsAndBrakesTheMotors) {
  MotorSafety s;
  AvrCommand c = driving();
  s.feed(100);
  EXPECT_FALSE(s.enforce(c, 100 + MotorSafety::kSilenceMs));
  EXPECT_TRUE(s.enforce(c, 101 + MotorSafety::kSilenceMs));
  EXPECT_EQ(s.reason(), MotorSafety::Reason::ControlSilent);
  EXPECT_EQ(c.pwm[0], 0);
  EXPECT_EQ(c.pwm[1], 0);
  EXPECT_EQ(c.pwm[2], 0);
  EXPECT_EQ(c.brakeMask, 0x07);
  EXPECT_EQ(c.inputPower, 0xF0);  // the sensors keep their supply
}

TEST(MotorSafety, SilenceWithTheMotorsAtRestIsNoFault) {
  MotorSafety s;
  AvrCommand c;  // all motors at 0 %
  s.feed(100);
  EXPECT_FALSE(s.enforce(c, 100 + 10 * MotorSafety::kSilenceMs));  // e.g. a long explorer decision
  EXPECT_FALSE(s.tripped());
  c.pwm[1] = 40;  // still silent, but now a wheel is driven
  EXPECT_TRUE(s.enforce(c, 101 + 10 * MotorSafety::kSilenceMs));
  EXPECT_EQ(s.reason(), MotorSafety::Reason::ControlSilent);
  EXPECT_EQ(c.pwm[1], 0);
}

TEST(MotorSafety, AFaultStaysLatchedUntilCleared) {
  MotorSafety s;
  s.trip(MotorSafety::Reason::Encoder);
  s.trip(MotorSafety::Reason::Check);  // the first reason wins
  for (uint32_t t = 0; t < 100; ++t) {
    s.feed(t);
    AvrCommand c = driving();  // the main loop keeps asking for power
    EXPECT_TRUE(s.enforce(c, t));
    EXPECT_EQ(c.pwm[0], 0);
  }
  EXPECT_EQ(s.reason(), MotorSafety::Reason::Encoder);
  s.clear();
  AvrCommand c = driving();
  s.feed(200);
  EXPECT_FALSE(s.enforce(c, 200));
  EXPECT_EQ(c.pwm[0], 60);
}

TEST(MotorSafety, NothingIsEnforcedBeforeTheLoopFirstRuns) {
  MotorSafety s;
  AvrCommand c = driving();
  EXPECT_FALSE(s.enforce(c, 100000));
}

}  // namespace
}  // namespace nxtmap::fw
