#include "host/sim/SimRobot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace nxtmap::sim {
namespace {

// Robot at (3,1): walls 1 cell north, 5 east, 4 south, 3 west => 5, 45, 35, 25 cm at 10 cm cells.
const World& room() {
  static const World w =
      World::fromRows({"#########", "#.......#", "#.......#", "#.......#", "#.......#", "#########"});
  return w;
}
constexpr int kWallCmByDirection[4] = {5, 45, 35, 25};  // N, E, S, W from cell (3,1)

NoiseProfile quiet() { return *noiseProfileByName("none"); }

struct PingCase {
  Heading heading;
  double mountCm;
};

class SimRobotPing : public ::testing::TestWithParam<PingCase> {};

TEST_P(SimRobotPing, ExactNoiseFreeDistancesForEverySensor) {
  SimRobot robot(room(), 3, 1, GetParam().heading, quiet(), 1, 255.0, GetParam().mountCm);
  for (int sensor = 0; sensor < 4; ++sensor) {
    const int direction = (static_cast<int>(GetParam().heading) + sensor) % 4;
    const int expected = static_cast<int>(std::lround(kWallCmByDirection[direction] - GetParam().mountCm));
    EXPECT_EQ(robot.ping(sensor), expected) << "sensor " << sensor;
  }
  EXPECT_EQ(robot.rawPings(), 4u);
}

INSTANTIATE_TEST_SUITE_P(AllHeadings, SimRobotPing,
                         ::testing::Values(PingCase{Heading::N, 0.0}, PingCase{Heading::E, 0.0},
                                           PingCase{Heading::S, 0.0}, PingCase{Heading::W, 0.0},
                                           PingCase{Heading::N, 3.0}, PingCase{Heading::W, 2.5}));

TEST(SimRobot, StartPoseIsCellCentre) {
  SimRobot robot(room(), 3, 1, Heading::W, quiet(), 1);
  EXPECT_DOUBLE_EQ(robot.cellCm(), 10.0);
  EXPECT_DOUBLE_EQ(robot.xCm(), 35.0);
  EXPECT_DOUBLE_EQ(robot.yCm(), 15.0);
  EXPECT_DOUBLE_EQ(robot.headingDeg(), 270.0);
  EXPECT_EQ(robot.col(), 3);
  EXPECT_EQ(robot.row(), 1);
  EXPECT_EQ(robot.nominalHeading(), Heading::W);
  EXPECT_EQ(robot.noise().name, "ideal");
}

TEST(SimRobot, NoEchoBeyondRange) {
  const World corridor =
      World::fromRows({std::string(40, '#'), "#" + std::string(38, '.') + "#", std::string(40, '#')});
  SimRobot robot(corridor, 1, 1, Heading::E, quiet(), 1);
  EXPECT_EQ(robot.ping(0), 255);  // wall 375 cm away
  EXPECT_EQ(robot.ping(2), 5);
  SimRobot shortRange(room(), 3, 1, Heading::N, quiet(), 1, 40.0);
  EXPECT_EQ(shortRange.ping(1), 255);  // 45 cm > 40 cm range
  EXPECT_EQ(shortRange.ping(2), 35);
  EXPECT_EQ(shortRange.ping(7), 255);  // no such sensor
}

TEST(SimRobot, ConeSeesObstacleBesideTheAxis) {
  const World w = World::fromRows({"#######", "#...#.#", "#.....#", "#.....#", "#.....#", "#######"});
  NoiseProfile wide = quiet();
  SimRobot narrow(w, 3, 4, Heading::N, wide, 1);
  EXPECT_EQ(narrow.ping(0), 35);
  wide.sonar.coneHalfAngleDeg = 12.0;
  wide.sonar.specularAngleDeg = 60.0;
  SimRobot coned(w, 3, 4, Heading::N, wide, 1);
  EXPECT_EQ(coned.ping(0), 26);  // block at (4,1): bottom face 25 cm ahead, reached by the 12 degree ray
}

TEST(SimRobot, ConeGetsNoEchoFromAWallParallelToTheBeam) {
  // Beside a long wall, the cone's outer rays meet the wall at a grazing angle: no echo from it,
  // so the reading is the far wall ahead, not the side wall.
  const World w = World::fromRows({"#########", "#.......#", "#.......#", "#########"});
  NoiseProfile p = quiet();
  p.sonar.coneHalfAngleDeg = 12.0;
  p.sonar.specularAngleDeg = 60.0;
  SimRobot r(w, 1, 1, Heading::E, p, 1);
  EXPECT_EQ(r.ping(0), 65);
}

TEST(SimRobot, DropoutSpecularAndCrosstalk) {
  NoiseProfile p = quiet();
  p.sonar.dropoutProb = 1.0;
  EXPECT_EQ(SimRobot(room(), 3, 1, Heading::N, p, 1).ping(1), 255);

  p = quiet();
  p.sonar.specularMissProb = 1.0;
  p.sonar.specularAngleDeg = 30.0;
  SimRobot spec(room(), 3, 2, Heading::N, p, 1);
  EXPECT_EQ(spec.ping(0), 15);  // head-on: echo
  spec.turn(1);                 // 45 degrees: grazing beyond 30 degrees
  EXPECT_EQ(spec.ping(0), 255);

  p = quiet();
  p.sonar.crosstalkProb = 1.0;
  SimRobot talk(room(), 3, 1, Heading::N, p, 1);
  EXPECT_EQ(talk.ping(1), 45);
  for (int i = 0; i < 50; ++i) {
    const int v = talk.ping(1, true);
    EXPECT_GE(v, 0);
    EXPECT_LE(v, 50);
  }
}

std::vector<int> scriptedRun(const NoiseProfile& p, uint64_t seed) {
  SimRobot robot(room(), 1, 1, Heading::E, p, seed);
  std::vector<int> out;
  for (int i = 0; i < 30; ++i) {
    for (int s = 0; s < 4; ++s) out.push_back(robot.ping(s, s % 2 == 0));
    if (i % 5 == 0) robot.turn(i % 2 == 0 ? 2 : -2);
    out.push_back(robot.move(1).cellsMoved);
  }
  out.push_back(static_cast<int>(std::lround(robot.xCm() * 1000)));
  return out;
}

TEST(SimRobot, SameSeedSameRunDifferentSeedDifferentRun) {
  const NoiseProfile typical = *noiseProfileByName("typical");
  EXPECT_EQ(scriptedRun(typical, 42), scriptedRun(typical, 42));
  EXPECT_NE(scriptedRun(typical, 42), scriptedRun(typical, 43));
  EXPECT_EQ(scriptedRun(quiet(), 1), scriptedRun(quiet(), 2));
}

TEST(SimRobot, TypicalNoiseStaysNearTruthWithBias) {
  SimRobot robot(room(), 3, 1, Heading::N, *noiseProfileByName("typical"), 7);
  double sum = 0.0;
  int echoes = 0;
  for (int i = 0; i < 2000; ++i) {
    const int v = robot.ping(1);
    if (v == 255) continue;
    EXPECT_NEAR(v, 45.5, 8.0);
    sum += v;
    ++echoes;
  }
  EXPECT_GT(echoes, 1900);
  EXPECT_NEAR(sum / echoes, 45.5, 0.3);
}

TEST(SimRobot, MoveStopsAtWall) {
  SimRobot robot(room(), 3, 1, Heading::E, quiet(), 1);
  const MoveResult fwd = robot.move(10);
  EXPECT_EQ(fwd.cellsMoved, 4);
  EXPECT_TRUE(fwd.blocked);
  EXPECT_EQ(robot.col(), 7);
  EXPECT_DOUBLE_EQ(robot.xCm(), 75.0);
  const MoveResult back = robot.move(-2);
  EXPECT_EQ(back.cellsMoved, -2);
  EXPECT_FALSE(back.blocked);
  EXPECT_EQ(robot.col(), 5);
  robot.turn(-2);  // face N, wall right ahead
  const MoveResult bump = robot.move(1);
  EXPECT_EQ(bump.cellsMoved, 0);
  EXPECT_TRUE(bump.blocked);
  EXPECT_EQ(robot.row(), 1);
  EXPECT_DOUBLE_EQ(robot.yCm(), 15.0);
}

TEST(SimRobot, SlipMovesTruePoseOnlyUnderNoise) {
  SimRobot exact(room(), 1, 2, Heading::E, quiet(), 3);
  EXPECT_EQ(exact.move(3).cellsMoved, 3);
  EXPECT_DOUBLE_EQ(exact.xCm(), 45.0);
  EXPECT_DOUBLE_EQ(exact.yCm(), 25.0);

  NoiseProfile slippy = quiet();
  slippy.wheels.slipSigma = 0.03;
  SimRobot slipping(room(), 1, 2, Heading::E, slippy, 3);
  EXPECT_EQ(slipping.move(3).cellsMoved, 3);
  EXPECT_NE(slipping.xCm(), 45.0);
  EXPECT_NEAR(slipping.xCm(), 45.0, 5.0);
  EXPECT_DOUBLE_EQ(slipping.yCm(), 25.0);  // heading exact: slip is along the axis only
  EXPECT_EQ(slipping.col(), 4);
}

TEST(SimRobot, TurnsInEighths) {
  SimRobot robot(room(), 3, 2, Heading::N, quiet(), 1);
  robot.turn(2);
  EXPECT_DOUBLE_EQ(robot.headingDeg(), 90.0);
  EXPECT_EQ(robot.nominalHeading(), Heading::E);
  robot.turn(-3);
  EXPECT_DOUBLE_EQ(robot.headingDeg(), 315.0);
  robot.turn(-1);
  EXPECT_DOUBLE_EQ(robot.headingDeg(), 270.0);
  EXPECT_EQ(robot.nominalHeading(), Heading::W);
  robot.turn(10);
  EXPECT_DOUBLE_EQ(robot.headingDeg(), 0.0);

  NoiseProfile wobbly = quiet();
  wobbly.wheels.turnSigmaDeg = 2.0;
  SimRobot noisy(room(), 3, 2, Heading::N, wobbly, 1);
  noisy.turn(2);
  EXPECT_NE(noisy.headingDeg(), 90.0);
  EXPECT_NEAR(noisy.headingDeg(), 90.0, 10.0);
  EXPECT_EQ(noisy.nominalHeading(), Heading::E);
}

TEST(NoiseProfiles, PresetsByName) {
  EXPECT_EQ(noiseProfileNames(), (std::vector<std::string>{"ideal", "typical", "nxt", "nxt-uncalibrated", "harsh"}));
  for (const auto& name : noiseProfileNames()) {
    const auto p = noiseProfileByName(name);
    ASSERT_TRUE(p) << name;
    EXPECT_EQ(p->name, name);
  }
  EXPECT_FALSE(noiseProfileByName("loud"));
  EXPECT_EQ(noiseProfileByName("none")->name, "ideal");  // the name older runs used
  const NoiseProfile none = *noiseProfileByName("ideal");
  EXPECT_EQ(none.sonar.rangeSigmaCm + none.sonar.dropoutProb + none.sonar.coneHalfAngleDeg + none.wheels.slipSigma +
                none.wheels.turnSigmaDeg,
            0.0);
  // typical: the model the published figures were measured with, value for value.
  const NoiseProfile typical = *noiseProfileByName("typical");
  EXPECT_DOUBLE_EQ(typical.sonar.rangeSigmaCm, 1.0);
  EXPECT_DOUBLE_EQ(typical.sonar.biasCm, 0.5);
  EXPECT_DOUBLE_EQ(typical.sonar.dropoutProb, 0.01);
  EXPECT_DOUBLE_EQ(typical.sonar.specularMissProb, 0.02);
  EXPECT_DOUBLE_EQ(typical.sonar.specularAngleDeg, 60.0);
  EXPECT_DOUBLE_EQ(typical.sonar.crosstalkProb, 0.02);
  EXPECT_DOUBLE_EQ(typical.sonar.coneHalfAngleDeg, 5.0);
  EXPECT_DOUBLE_EQ(typical.wheels.slipSigma, 0.01);
  EXPECT_DOUBLE_EQ(typical.wheels.turnSigmaDeg, 0.5);
  const NoiseProfile harsh = *noiseProfileByName("harsh");
  EXPECT_GT(harsh.sonar.dropoutProb, typical.sonar.dropoutProb);
  EXPECT_GT(harsh.wheels.turnSigmaDeg, typical.wheels.turnSigmaDeg);
}

TEST(HeadingFromChar, ParsesCompassLetters) {
  EXPECT_EQ(headingFromChar('N'), Heading::N);
  EXPECT_EQ(headingFromChar('e'), Heading::E);
  EXPECT_EQ(headingFromChar('S'), Heading::S);
  EXPECT_EQ(headingFromChar('w'), Heading::W);
  EXPECT_FALSE(headingFromChar('x'));
}

}  // namespace
}  // namespace nxtmap::sim
