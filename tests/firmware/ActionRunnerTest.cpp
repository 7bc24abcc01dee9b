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
  DriveEvent carryOut(const DriveAction& a, uint32_t limitMs = 20000) {
    runner.begin(a, wheels(), now);
    DriveEvent e;
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

TEST(ActionRunner, DriveOneCellForwardAndBack) {
  Robot r;
  DriveEvent e = r.carryOut(DriveAction::drive(200));
  EXPECT_EQ(e.kind, DriveEvent::Kind::Driven);
  EXPECT_FALSE(e.blocked);
  EXPECT_NEAR(r.count[0], 409, 3);
  EXPECT_NEAR(r.count[1], 409, 3);
  e = r.carryOut(DriveAction::drive(-200));
  EXPECT_EQ(e.kind, DriveEvent::Kind::Driven);
  EXPECT_NEAR(r.count[0], 0, 3);
  EXPECT_EQ(r.runner.power(0), 0);
}

TEST(ActionRunner, RotationsSpinTheWheelsOppositeWays) {
  Robot r;
  DriveEvent e = r.carryOut(DriveAction::rotate(1571));  // 90 deg clockwise
  EXPECT_EQ(e.kind, DriveEvent::Kind::Rotated);
  EXPECT_NEAR(r.count[0], 180, 3);
  EXPECT_NEAR(r.count[1], -180, 3);
  e = r.carryOut(DriveAction::rotate(-785));
  EXPECT_NEAR(r.count[0], 90, 3);
  EXPECT_NEAR(r.count[1], -90, 3);
  EXPECT_EQ(r.runner.failedRotations(), 0u);
}

TEST(ActionRunner, ABlockedDriveReturnsToItsStartAndSaysSo) {
  Robot r;
  r.wallAt = 150;
  const DriveEvent e = r.carryOut(DriveAction::drive(200));
  EXPECT_EQ(e.kind, DriveEvent::Kind::Driven);
  EXPECT_TRUE(e.blocked);
  EXPECT_NEAR(r.count[0], 0, 3);  // back where the move began
  EXPECT_NEAR(r.count[1], 0, 3);
}

TEST(ActionRunner, AStoppedDriveResumesToItsOriginalTarget) {
  Robot r;
  r.runner.begin(DriveAction::drive(200), r.wheels(), r.now);
  DriveEvent e;
  // Drive part of the way, then stop.
  for (int i = 0; i < 2000 && r.count[0] < 150; ++i, ++r.now) {
    ASSERT_FALSE(r.runner.poll(r.wheels(), r.now, e));
    for (int w = 0; w < 2; ++w) {
      r.acc[w] += r.runner.power(w) * 8;
      r.count[w] += r.acc[w] / 1000;
      r.acc[w] %= 1000;
    }
  }
  r.runner.abort();
  EXPECT_EQ(r.runner.power(0), 0);
  EXPECT_FALSE(r.runner.busy());
  const int32_t stoppedAt = r.count[0];
  EXPECT_GE(stoppedAt, 150);
  ASSERT_TRUE(r.runner.resume(r.wheels(), r.now));
  bool done = false;
  for (int i = 0; i < 20000 && !done; ++i, ++r.now) {
    done = r.runner.poll(r.wheels(), r.now, e);
    for (int w = 0; w < 2; ++w) {
      r.acc[w] += r.runner.power(w) * 8;
      r.count[w] += r.acc[w] / 1000;
      r.acc[w] %= 1000;
    }
  }
  ASSERT_TRUE(done);
  EXPECT_EQ(e.kind, DriveEvent::Kind::Driven);
  EXPECT_FALSE(e.blocked);
  EXPECT_NEAR(r.count[0], 409, 3);  // one cell in all, not 150 + one cell
  EXPECT_NEAR(r.count[1], 409, 3);
  EXPECT_FALSE(r.runner.resume(r.wheels(), r.now));  // nothing left to resume
}

TEST(ActionRunner, ThinkIsAnsweredOnTheNextPollWithoutMoving) {
  Robot r;
  r.runner.begin(DriveAction::think(), r.wheels(), r.now);
  EXPECT_TRUE(r.runner.busy());
  DriveEvent e;
  ASSERT_TRUE(r.runner.poll(r.wheels(), r.now, e));
  EXPECT_EQ(e.kind, DriveEvent::Kind::Thought);
  EXPECT_EQ(r.runner.power(0), 0);
  EXPECT_FALSE(r.runner.busy());
}

TEST(ActionRunner, AReadFiltersSamplesOfTheSensorsPort) {
  Robot r;
  r.sensors[3].regs[0x42] = 55;  // Left = port 4
  r.sensors[0].regs[0x42] = 200;
  const DriveEvent e = r.carryOut(DriveAction::read(Sensor::Left));
  ASSERT_EQ(e.kind, DriveEvent::Kind::Range);
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
  const DriveEvent e = r.carryOut(DriveAction::read(Sensor::Front));
  ASSERT_EQ(e.kind, DriveEvent::Kind::Range);
  EXPECT_EQ(e.reading.status, RangeStatus::NoEcho);
}

}  // namespace
}  // namespace nxtmap::fw::test
