#include <gtest/gtest.h>

#include "firmware/app/ActionRunner.hpp"
#include "tests/firmware/I2cSlaveModel.hpp"

namespace nxtmap::fw::test {
namespace {

// The robot around an ActionRunner: two wheels following power (800 deg/s at 100 %), an optional
// obstacle stalling forward motion beyond `wallAt` counts, and one ultrasonic sensor per port
// reached through the soft I2C engine.
struct Robot {
  MotionController motion;
  SoftI2c i2c;
  SonarSequencer sonar{i2c};
  MotionGeometry drive{};
  RangeGeometry range{20, 7, 120, 6};
  uint8_t ports[4] = {0, 1, 2, 3};
  ActionRunner runner{motion, sonar, drive, range, ports};
  I2cSlaveModel sensors[4] = {I2cSlaveModel{1}, I2cSlaveModel{1}, I2cSlaveModel{1}, I2cSlaveModel{1}};
  int32_t count[2] = {0, 0}, acc[2] = {0, 0};
  int32_t wallAt = 1 << 30;
  uint32_t now = 1000;

  Robot() { sonar.powered(0); }
  ActionRunner::Wheels wheels() const { return {count[0], count[1]}; }
  // Runs until the runner answers; returns the event.
  Event carryOut(const Action& a, uint32_t limitMs = 20000) {
    runner.begin(a, wheels(), now);
    Event e;
    for (uint32_t i = 0; i < limitMs; ++i, ++now) {
      if (runner.poll(wheels(), now, e)) return e;
      for (int w = 0; w < 2; ++w) {
        const int8_t p = runner.power(w);
        if (count[w] >= wallAt && p > 0) continue;
        acc[w] += p * 8;
        count[w] += acc[w] / 1000;
        acc[w] %= 1000;
      }
      if (i2c.busy())
        for (int t = 0; t < 29; ++t) i2c.tick(sensors[sonar.port()]);
    }
    ADD_FAILURE() << "action did not finish";
    return e;
  }
};

TEST(ActionRunner, MoveOneCellForwardAndBack) {
  Robot r;
  Event e = r.carryOut(Action::move(1));
  EXPECT_EQ(e.kind, Event::Kind::Moved);
  EXPECT_EQ(e.amount, 1);
  EXPECT_NEAR(r.count[0], 409, 3);
  EXPECT_NEAR(r.count[1], 409, 3);
  e = r.carryOut(Action::move(-1));
  EXPECT_EQ(e.kind, Event::Kind::Moved);
  EXPECT_EQ(e.amount, -1);
  EXPECT_NEAR(r.count[0], 0, 3);
  EXPECT_EQ(r.runner.power(0), 0);
}

TEST(ActionRunner, TurnsSpinTheWheelsOppositeWays) {
  Robot r;
  Event e = r.carryOut(Action::turn(2));
  EXPECT_EQ(e.kind, Event::Kind::Turned);
  EXPECT_EQ(e.amount, 2);
  EXPECT_NEAR(r.count[0], 180, 3);
  EXPECT_NEAR(r.count[1], -180, 3);
  e = r.carryOut(Action::turn(-1));
  EXPECT_NEAR(r.count[0], 90, 3);
  EXPECT_NEAR(r.count[1], -90, 3);
  EXPECT_EQ(r.runner.failedTurns(), 0u);
}

TEST(ActionRunner, ABlockedMoveReturnsToItsStartAndAnswersBlocked) {
  Robot r;
  r.wallAt = 150;
  const Event e = r.carryOut(Action::move(1));
  EXPECT_EQ(e.kind, Event::Kind::Blocked);
  EXPECT_NEAR(r.count[0], 0, 3);  // back where the move began
  EXPECT_NEAR(r.count[1], 0, 3);
}

TEST(ActionRunner, AReadFiltersSamplesOfTheSensorsPort) {
  Robot r;
  r.sensors[3].regs[0x42] = 55;  // Left = port 4
  r.sensors[0].regs[0x42] = 200;
  const Event e = r.carryOut(Action::read(Sensor::Left));
  ASSERT_EQ(e.kind, Event::Kind::Range);
  EXPECT_EQ(e.sensor, Sensor::Left);
  EXPECT_EQ(e.reading.status, RangeStatus::Good);
  EXPECT_EQ(e.reading.cm, 55);
  EXPECT_EQ(e.reading.samples, RangeFilter::kAgree);
  EXPECT_TRUE(r.sensors[0].registerWrites.empty());  // the other sensors stayed quiet
  EXPECT_EQ(r.sensors[3].registerWrites.size(), RangeFilter::kAgree);
}

TEST(ActionRunner, ASilentSensorGivesNoEcho) {
  Robot r;
  for (auto& s : r.sensors) s.present = false;
  const Event e = r.carryOut(Action::read(Sensor::Front));
  ASSERT_EQ(e.kind, Event::Kind::Range);
  EXPECT_EQ(e.reading.status, RangeStatus::NoEcho);
}

}  // namespace
}  // namespace nxtmap::fw::test
