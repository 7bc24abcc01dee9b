// DriveModel's stretches: a move of the emulated motors carries the random errors of one of the host's
// commands however often the controller changes the motors' power on the way. A 90 degree spin under
// `nxt` wheels (turnSigmaDeg 2) ends with a turn error of 2 degrees (1 sigma) and a straight one cell
// with 3 % slip whether the power is held or stepped every millisecond (a power change used to draw a new
// factor: a ramping controller averaged the errors away and the emulated wheels were kinder than the host's).
#include "host/emu/AvrModel.hpp"
#include "host/emu/Clock.hpp"
#include "host/emu/DriveModel.hpp"
#include "host/emu/Pioa.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/WheelNoise.hpp"
#include "host/sim/World.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace nxtmap::emu {
namespace {

// The AVR's 9-byte command: power byte, PWM frequency, motor powers A-D, brake mask, input power, checksum.
std::vector<uint8_t> command(int a, int b) {
  std::vector<uint8_t> f{
      0, 8, static_cast<uint8_t>(static_cast<int8_t>(a)), static_cast<uint8_t>(static_cast<int8_t>(b)), 0, 0, 0, 0};
  unsigned sum = 0;
  for (uint8_t v : f) sum += v;
  f.push_back(static_cast<uint8_t>(0xFF - (sum & 0xFF)));
  return f;
}

const sim::World& hall() {
  static const sim::World w = sim::World::fromRows(
      {"#########", "#.......#", "#.......#", "#.......#", "#.......#", "#.......#", "#.......#", "#########"});
  return w;
}

sim::NoiseProfile randomOnly(double slipSigma, double turnSigmaDeg) {
  sim::NoiseProfile n = *sim::noiseProfileByName("ideal");
  n.wheels = sim::WheelNoise{};
  n.wheels.slipSigma = slipSigma;
  n.wheels.turnSigmaDeg = turnSigmaDeg;
  return n;
}

struct Move {
  double headingDeg, distanceCm;  // where the robot ended, from its start (facing N, clockwise +)
};

// Drives motors A (left) and B (right) at +-50 % for `ms`; stepped: the power alternates between 50 and 49
// every millisecond, as a controller's output does. Then both stop.
Move drive(const sim::NoiseProfile& noise, uint64_t seed, bool spin, int ms, bool stepped) {
  Clock clock;
  AvrModel avr;
  Pioa pio(clock);
  sim::SimRobot robot(hall(), 4, 4, sim::Heading::N, noise, seed);
  DriveModel drive(clock, avr, pio, robot, DriveGeometry{}, seed);
  const double x0 = robot.xCm(), y0 = robot.yCm();
  for (int t = 0; t < ms; ++t) {
    const int p = stepped && t % 2 == 1 ? 49 : 50;
    avr.receive(command(p, spin ? -p : p));
    clock.now += cyclesFromMs(1);
    drive.advanceTo(clock.now);
  }
  avr.receive(command(0, 0));
  clock.now += cyclesFromMs(1);
  drive.advanceTo(clock.now);
  return Move{robot.headingDeg(), std::hypot(robot.xCm() - x0, robot.yCm() - y0)};
}

double sigma(const std::vector<double>& v) {
  double mean = 0.0, sq = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (double x : v) sq += (x - mean) * (x - mean);
  return std::sqrt(sq / static_cast<double>(v.size() - 1));
}

constexpr int kRuns = 400;
constexpr int kSpinMs = 450;      // 50 % = 400 deg/s at the motor: about 90 degrees of robot turn
constexpr int kStraightMs = 500;  // about 10 cm

TEST(DriveModelStretch, NoRandomErrorsMoveTheRobotExactlyAsTheMotorsTurn) {
  const sim::NoiseProfile none = randomOnly(0.0, 0.0);
  const Move spin = drive(none, 1, true, kSpinMs, true);
  EXPECT_EQ(drive(none, 2, true, kSpinMs, true).headingDeg, spin.headingDeg);
  EXPECT_GT(spin.headingDeg, 60.0);
  const Move straight = drive(none, 1, false, kStraightMs, false);
  EXPECT_EQ(drive(none, 2, false, kStraightMs, false).distanceCm, straight.distanceCm);
  EXPECT_GT(straight.distanceCm, 5.0);
}

struct StretchCase {
  const char* what;
  bool spin, stepped;
};
class DriveModelStretchNoise : public ::testing::TestWithParam<StretchCase> {};

// One spin: the turn error has the host's sigma for the turn made (2 deg * turn / 90); one straight: 3 %.
TEST_P(DriveModelStretchNoise, OneMoveCarriesOneCommandsErrorHoweverThePowerSteps) {
  const StretchCase c = GetParam();
  const sim::NoiseProfile noisy = randomOnly(0.03, 2.0), none = randomOnly(0.0, 0.0);
  const int ms = c.spin ? kSpinMs : kStraightMs;
  const Move clean = drive(none, 1, c.spin, ms, c.stepped);
  std::vector<double> errors;
  for (uint64_t seed = 1; seed <= kRuns; ++seed) {
    const Move m = drive(noisy, seed, c.spin, ms, c.stepped);
    errors.push_back(c.spin ? m.headingDeg - clean.headingDeg : m.distanceCm / clean.distanceCm - 1.0);
  }
  const double expected = c.spin ? 2.0 * clean.headingDeg / 90.0 : 0.03;
  // 400 draws: the sample sigma lies within 10 % of the true one with a margin of about 3 standard errors.
  EXPECT_NEAR(sigma(errors), expected, 0.1 * expected) << c.what;
}

INSTANTIATE_TEST_SUITE_P(HeldOrStepped, DriveModelStretchNoise,
                         ::testing::Values(StretchCase{"spin, power held", true, false},
                                           StretchCase{"spin, power stepped every ms", true, true},
                                           StretchCase{"straight, power held", false, false},
                                           StretchCase{"straight, power stepped every ms", false, true}));

TEST(DriveModelStretch, AStraightMoveDoesNotTurnAtRandomAndASpinDoesNotSlip) {
  const sim::NoiseProfile noisy = randomOnly(0.03, 2.0), none = randomOnly(0.0, 0.0);
  const Move straight = drive(none, 1, false, kStraightMs, true), spin = drive(none, 1, true, kSpinMs, true);
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    EXPECT_NEAR(drive(noisy, seed, false, kStraightMs, true).headingDeg, straight.headingDeg, 1e-9);
    EXPECT_NEAR(drive(noisy, seed, true, kSpinMs, true).distanceCm, spin.distanceCm, 1e-9);
  }
}

}  // namespace
}  // namespace nxtmap::emu
