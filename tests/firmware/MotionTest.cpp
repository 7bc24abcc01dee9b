#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "firmware/drivers/MotionController.hpp"
#include "firmware/drivers/MotionGeometry.hpp"

namespace nxtmap::fw {
namespace {

TEST(MotionGeometry, CountsFromMillimetresCellsAndAngles) {
  const MotionGeometry g;               // 56 mm wheel, 112 mm track, 200 mm cell
  EXPECT_EQ(g.countsForCells(1), 409);  // 200 / (pi * 56) * 360 = 409.3
  EXPECT_EQ(g.countsForCells(-1), -409);
  EXPECT_EQ(g.countsForMm(176), 360);  // one wheel turn = pi * 56 = 175.9 mm
  EXPECT_EQ(g.countsForTurn(2), 180);  // 90 deg spin: quarter of the track circle
  EXPECT_EQ(g.countsForTurn(1), 90);
  EXPECT_EQ(g.countsForTurn(-2), -180);
  EXPECT_EQ(g.countsForMrad(1571), 180);
  EXPECT_EQ(g.countsForMrad(-785), -90);
  EXPECT_EQ(g.countsForMrad(10), 1);
}

// Two wheels without inertia: each ms a wheel turns power x speed / 1000 counts (fractions kept);
// speed 8 = 800 deg/s at 100 %, like the NXT motor.
struct FinePlant {
  int32_t count[2] = {0, 0};
  int32_t acc[2] = {0, 0};
  int32_t speedPer10[2] = {8, 8};
  int32_t wallAt = 1 << 30;  // left wheel stalls beyond this many counts forward
  void step(int8_t pl, int8_t pr) {
    const int8_t p[2] = {pl, pr};
    for (int w = 0; w < 2; ++w) {
      if (count[w] >= wallAt && p[w] > 0) continue;
      acc[w] += p[w] * speedPer10[w];
      count[w] += acc[w] / 1000;
      acc[w] %= 1000;
    }
  }
};

MotionController::Status run(MotionController& m, FinePlant& p, uint32_t& now, int maxMs) {
  MotionController::Status s = m.status();
  for (int i = 0; i < maxMs; ++i, ++now) {
    s = m.update(p.count[0], p.count[1], now);
    if (s != MotionController::Status::Running) break;
    p.step(m.power(0), m.power(1));
  }
  return s;
}

TEST(MotionController, ReachesTheTargetCountsOfAStraightMove) {
  MotionController m;
  FinePlant p;
  uint32_t now = 1000;
  m.start(0, 0, 409, 409, now);
  EXPECT_EQ(run(m, p, now, 10000), MotionController::Status::Done);
  EXPECT_NEAR(p.count[0], 409, 3);
  EXPECT_NEAR(p.count[1], 409, 3);
  EXPECT_EQ(m.power(0), 0);
  EXPECT_EQ(m.power(1), 0);
}

// A move ends on the counts it was asked for, not a count short: a spin of one count (half a degree) is a heading
// correction, and a turn a count short is half a degree off.
TEST(MotionController, EndsEachWheelOnItsTargetCount) {
  struct Row {
    int32_t left, right;
  };
  const Row rows[] = {{1, -1}, {-1, 1}, {2, 2}, {10, -10}, {-10, 10}, {180, -180}, {409, 409}, {-409, -409}};
  for (const Row& r : rows) {
    MotionController m;
    FinePlant p;
    uint32_t now = 1000;
    m.start(0, 0, r.left, r.right, now);
    EXPECT_EQ(run(m, p, now, 10000), MotionController::Status::Done) << r.left << "," << r.right;
    EXPECT_EQ(p.count[0], r.left);
    EXPECT_EQ(p.count[1], r.right);
  }
}

TEST(MotionController, SpinTurnDrivesTheWheelsInOppositeDirections) {
  MotionController m;
  FinePlant p;
  p.count[0] = 5000;
  p.count[1] = -300;
  uint32_t now = 0;
  m.start(p.count[0], p.count[1], 180, -180, now);
  m.update(p.count[0], p.count[1], now);
  EXPECT_GT(m.power(0), 0);
  EXPECT_LT(m.power(1), 0);
  EXPECT_EQ(run(m, p, now, 10000), MotionController::Status::Done);
  EXPECT_NEAR(p.count[0], 5180, 3);
  EXPECT_NEAR(p.count[1], -480, 3);
}

TEST(MotionController, KeepsTheWheelsTogetherWhenOneMotorIsStronger) {
  MotionController m;
  FinePlant p;
  p.speedPer10[0] = 11;  // left motor ~40 % stronger
  uint32_t now = 0;
  m.start(0, 0, 800, 800, now);
  int32_t worstLead = 0;
  for (int i = 0; i < 10000 && m.status() != MotionController::Status::Done; ++i, ++now) {
    m.update(p.count[0], p.count[1], now);
    p.step(m.power(0), m.power(1));
    worstLead = std::max(worstLead, std::abs(p.count[0] - p.count[1]));
  }
  EXPECT_EQ(m.status(), MotionController::Status::Done);
  EXPECT_LE(worstLead, 25);  // without the sync term the left wheel would lead by ~40 %
}

TEST(MotionController, AStalledWheelIsReportedBlocked) {
  MotionController m;
  FinePlant p;
  p.wallAt = 100;
  p.count[1] = 0;
  uint32_t now = 0;
  m.start(0, 0, 409, 409, now);
  // The right wheel also stalls at the wall (the robot is stuck).
  for (int i = 0; i < 20000 && m.status() == MotionController::Status::Running; ++i, ++now) {
    m.update(p.count[0], p.count[1], now);
    const int8_t r = p.count[1] >= 100 ? 0 : m.power(1);
    p.step(m.power(0), r);
  }
  EXPECT_EQ(m.status(), MotionController::Status::Blocked);
  EXPECT_NEAR(m.travelled(0), 100, 2);
  EXPECT_EQ(m.power(0), 0);
  EXPECT_EQ(m.power(1), 0);
}

TEST(MotionController, StopAndIdleGiveZeroPower) {
  MotionController m;
  EXPECT_EQ(m.update(0, 0, 0), MotionController::Status::Idle);
  m.start(0, 0, 100, 100, 0);
  m.update(0, 0, 1);
  EXPECT_NE(m.power(0), 0);
  m.stop();
  EXPECT_EQ(m.status(), MotionController::Status::Idle);
  EXPECT_EQ(m.power(0), 0);
  EXPECT_EQ(m.update(0, 0, 2), MotionController::Status::Idle);
}

}  // namespace
}  // namespace nxtmap::fw
