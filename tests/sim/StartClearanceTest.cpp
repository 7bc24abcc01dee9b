// Where a person sets down a robot whose body sweeps out of its 20 cm cell when it turns (the brick's
// 16 x 18 cm body reaches 12 cm): with room to turn, or moved by whole cells to the nearest spot that has it.
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/StartClearance.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace nxtmap::sim {
namespace {

// The centre of raster cell (col, row) of 20 cm cells.
StartPose cellCentre(int col, int row, double headingDeg = 0.0) {
  return StartPose{Vec2((col + 0.5) * 20.0, (row + 0.5) * 20.0), headingDeg};
}

TEST(StartClearance, AStartWithoutRoomToTurnMovesToTheNearestSpotWithRoom) {
  struct Row {
    const char* name;
    std::vector<std::string> rows;
    StartPose start;
    double movedCm;  // < 0: no spot with room
  };
  const std::vector<std::string> room = {"#######", "#.....#", "#.....#", "#.....#", "#.....#", "#######"};
  const std::vector<Row> table = {
      {"in the open: stays", room, cellCentre(3, 2), 0.0},
      {"a corner cell: one cell on diagonally", room, cellCentre(1, 1), 20.0 * std::sqrt(2.0)},
      {"beside one wall: one cell away from it", room, cellCentre(3, 1), 20.0},
      // 3 cm off the centre and turned 5 degrees, its cells reach 3 cm more one way: two cells down, one across.
      {"a set-down off the centre keeps its offset", room, StartPose{Vec2(33.0, 27.0), 5.0}, 20.0 * std::sqrt(5.0)},
      {"a corridor one cell wide: nowhere", {"#########", "#.......#", "#########"}, cellCentre(4, 1), -1.0},
  };
  for (const Row& r : table) {
    const World world = World::fromRows(r.rows, 0.20);
    const Site site = siteFromRaster(world);
    const ClearStart c = withRoomToTurn(*site.scene, r.start, 20.0, 12.1);
    EXPECT_NEAR(c.movedCm, r.movedCm, 1e-9) << r.name;
    EXPECT_DOUBLE_EQ(c.pose.headingDeg, r.start.headingDeg) << r.name;
    EXPECT_EQ(roomToTurnAt(*site.scene, c.pose, 20.0, 12.1), r.movedCm >= 0.0) << r.name;
    EXPECT_EQ(c.pose.cm == r.start.cm, r.movedCm <= 0.0) << r.name;
  }
}

TEST(StartClearance, ASpotBehindAWallIsNotWhereThePersonCarriesIt) {
  // The start's own room has no spot with room; the one beyond the wall does, but is not in sight.
  const World world = World::fromRows({"#########", "#...#...#", "#...#...#", "#...#...#", "#########"},
                                      0.20);  // two rooms 3 cells wide
  const Site site = siteFromRaster(world);
  const ClearStart c = withRoomToTurn(*site.scene, cellCentre(1, 1), 20.0, 12.1);
  EXPECT_DOUBLE_EQ(c.movedCm, 20.0 * std::sqrt(2.0));  // (2, 2): the middle of its own room
  EXPECT_LT(c.pose.cm.x(), 80.0);                      // west of the dividing wall
}

TEST(StartClearance, AStartInAPassageIsCarriedRoundTheWallToTheRoomBeyondIt) {
  // Set down in a passage one cell wide below a wall with a gap at each end: the nearest spot with room, (4, 2),
  // is three cells up, behind the wall (not in a straight line), and reached through the gap at column 1.
  const World world = World::fromRows(
      {"##########", "#........#", "#........#", "#........#", "#.######.#", "#........#", "##########"}, 0.20);
  const Site site = siteFromRaster(world);
  const ClearStart c = withRoomToTurn(*site.scene, cellCentre(4, 5), 20.0, 12.1);
  EXPECT_NEAR(c.movedCm, 60.0, 1e-9);
  EXPECT_NEAR(c.pose.cm.x(), cellCentre(4, 2).cm.x(), 1e-9);
  EXPECT_NEAR(c.pose.cm.y(), cellCentre(4, 2).cm.y(), 1e-9);
}

TEST(StartClearance, OnlyABodyThatSweepsOutOfItsCellIsMoved) {
  const World world = World::fromRows({"#######", "#.....#", "#.....#", "#.....#", "#.....#", "#######"}, 0.20);
  const Site site = siteFromRaster(world);
  const RobotPlacement brick = placeRobot(site, *robotByName("brick"), cellCentre(1, 1), 0.0, 1);
  EXPECT_TRUE(robotByName("brick")->turnNeedsRoom());
  EXPECT_NEAR(brick.startMovedCm, 20.0 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(brick.grid.startCol, 2);
  EXPECT_EQ(brick.grid.startRow, 2);
  const RobotPlacement point = placeRobot(site, pointRobotFor(20), cellCentre(1, 1), 0.0, 1);
  EXPECT_FALSE(pointRobotFor(20).turnNeedsRoom());
  EXPECT_EQ(point.startMovedCm, 0.0);
  EXPECT_EQ(point.grid.startCol, 1);
}

}  // namespace
}  // namespace nxtmap::sim
