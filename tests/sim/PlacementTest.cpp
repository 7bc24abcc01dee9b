// Setting a robot down: the start jitter, the robot's grid and truth (RobotPlacement), and the body.
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/StartJitter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace nxtmap::sim {
namespace {

const World& room() {  // 8 x 6 cells of 10 cm, walls round a 6 x 4 floor
  static const World w = World::fromRows({"########", "#......#", "#......#", "#......#", "#......#", "########"});
  return w;
}

TEST(StartJitter, ZeroIsTheNominalPoseAndAnyOtherStaysInsideTheCell) {
  const StartPose nominal{Vec2(35.0, 25.0), 90.0};
  const StartPose same = jitterStart(nominal, 20.0, 0.0, 7);
  EXPECT_EQ(same.cm, nominal.cm);
  EXPECT_EQ(same.headingDeg, nominal.headingDeg);
  std::set<double> headings;
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    const StartPose p = jitterStart(nominal, 20.0, 10.0, seed);
    EXPECT_LE(std::fabs(p.cm.x() - 35.0), 9.0 + 1e-9);  // 0.45 of a 20 cm cell
    EXPECT_LE(std::fabs(p.cm.y() - 25.0), 9.0 + 1e-9);
    EXPECT_LE(std::fabs(p.headingDeg - 90.0), 10.0);
    headings.insert(p.headingDeg);
    const StartPose again = jitterStart(nominal, 20.0, 10.0, seed);
    EXPECT_EQ(again.cm, p.cm);  // same seed, same pose
  }
  EXPECT_GT(headings.size(), 190u);
}

struct SquareCase {
  double headingDeg;
  int quarter;
  double remainderDeg;
};

TEST(StartJitter, SquareQuarterAndRemainderTable) {
  for (const SquareCase c : {SquareCase{0, 0, 0},
                             {3, 0, 3},
                             {-7, 0, -7},
                             {88, 1, -2},
                             {181, 2, 1},
                             {275, 3, 5},
                             {359, 0, -1},
                             {-92, 3, -2}}) {
    EXPECT_EQ(squareQuarter(c.headingDeg), c.quarter) << c.headingDeg;
    EXPECT_NEAR(squareRemainderDeg(c.headingDeg), c.remainderDeg, 1e-9) << c.headingDeg;
  }
  EXPECT_EQ(startJitterProblem(0), "");
  EXPECT_EQ(startJitterProblem(45), "");
  EXPECT_NE(startJitterProblem(45.5), "");
  EXPECT_NE(startJitterProblem(-1), "");
  EXPECT_NE(startJitterProblem(std::nan("")), "");
}

TEST(RobotPlacement, ASquareStartOnTheRastersOwnCellsKeepsTheRasterAsTruth) {
  const Site site = siteFromRaster(room());
  const RobotPlacement p = placeRobot(site, pointRobotFor(10), site.rasterStart(3, 2, 90.0), 0.0, 1);
  EXPECT_EQ(p.grid.startCol, 3);
  EXPECT_EQ(p.grid.startRow, 2);
  EXPECT_EQ(p.heading, Heading::E);
  ASSERT_EQ(p.truth.width(), room().width());
  for (int r = 0; r < room().height(); ++r)
    for (int c = 0; c < room().width(); ++c) EXPECT_EQ(p.truth.blocked(c, r), room().blocked(c, r)) << c << "," << r;
}

TEST(RobotPlacement, AJitteredStartTurnsTheRobotsGridWithIt) {
  const Site site = siteFromRaster(room());
  const RobotPlacement p = placeRobot(site, pointRobotFor(10), site.rasterStart(3, 2, 0.0), 10.0, 5);
  EXPECT_NEAR(p.grid.frame.headingDeg, squareRemainderDeg(p.start.headingDeg), 1e-12);
  EXPECT_NE(p.grid.frame.headingDeg, 0.0);
  const Vec2 centre = p.grid.frame.toPlane(Vec2(p.grid.startCol, p.grid.startRow));
  EXPECT_NEAR((centre - p.start.cm).norm(), 0.0, 1e-9);  // the true start is its start cell's centre
  EXPECT_FALSE(p.truth.blocked(p.grid.startCol, p.grid.startRow));
}

TEST(RobotPlacement, TheBricksCellsOnATenCentimetreWorldAreItsOwn) {
  const Site site = siteFromRaster(room());
  const RobotPlacement p = placeRobot(site, *robotByName("brick"), site.rasterStart(3, 2, 0.0), 0.0, 1);
  EXPECT_DOUBLE_EQ(p.truth.resolutionM(), 0.20);
  EXPECT_FALSE(p.truth.blocked(p.grid.startCol, p.grid.startRow));
}

TEST(SimRobotBody, TheBodyStallsWhereAPointWouldPass) {
  // A 16 x 18 cm body in a corridor 20 cm wide (one free row of 20 cm cells) cannot turn on the spot:
  // its corners reach 12 cm from its centre.
  const World corridor = World::fromRows({"##########", "#........#", "##########"}, 0.20);
  const Site site = siteFromRaster(corridor);
  const NoiseProfile ideal = *noiseProfileByName("ideal");
  const RobotPlacement brick = placeRobot(site, *robotByName("brick"), site.rasterStart(4, 1, 90.0), 0.0, 1);
  SimRobot body(brick.scene, brick.robot, brick.grid.frame, brick.start.cm, brick.start.headingDeg, ideal, 1);
  EXPECT_TRUE(body.drive(40.0));    // along the corridor: fits
  EXPECT_FALSE(body.rotate(90.0));  // across it: the corners meet the walls
  EXPECT_LT(std::fabs(body.headingDeg() - 90.0), 45.0);
  // The encoders measure the share carried out: ideal wheels turn the body by exactly that much.
  EXPECT_GT(body.lastSpinShare(), 0.0);
  EXPECT_LT(body.lastSpinShare(), 0.5);
  EXPECT_NEAR(body.headingDeg(), 90.0 + 90.0 * body.lastSpinShare(), 1e-9);
  EXPECT_TRUE(body.rotate(-90.0 * body.lastSpinShare()));  // back the way it came
  EXPECT_DOUBLE_EQ(body.lastSpinShare(), 1.0);
  const RobotPlacement point = placeRobot(site, pointRobotFor(20), site.rasterStart(4, 1, 90.0), 0.0, 1);
  SimRobot dot(point.scene, point.robot, point.grid.frame, point.start.cm, point.start.headingDeg, ideal, 1);
  EXPECT_TRUE(dot.rotate(90.0));
  EXPECT_DOUBLE_EQ(dot.headingDeg(), 180.0);
}

}  // namespace
}  // namespace nxtmap::sim
