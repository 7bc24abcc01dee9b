#include <gtest/gtest.h>

#include "common/interpret/Doorway.hpp"
#include "common/interpret/RoomInterpretation.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

std::vector<Doorway> find(test::GridFixture& f, const DoorwayLimits& limits = DoorwayLimits{}) {
  Doorway out[16];
  const uint8_t n = findDoorways(f.grid(), f.grid().window(), limits, out, 16);
  return std::vector<Doorway>(out, out + n);
}

TEST(Doorway, GapInAThinWallBetweenTwoRooms) {
  test::GridFixture f;
  f.draw({"#########", "#.......#", "#.......#", "###...###", "#.......#", "#.......#", "#########"});
  const std::vector<Doorway> d = find(f);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_TRUE(d[0].alongX);
  EXPECT_EQ(d[0].first, (Cell{3, 3}));
  EXPECT_EQ(d[0].width, 3);
  EXPECT_EQ(d[0].depth, 1);
  EXPECT_EQ(d[0].middle(), (Cell{4, 3}));
  EXPECT_TRUE(d[0].contains(Cell{5, 3}));
  EXPECT_FALSE(d[0].contains(Cell{6, 3}));
}

TEST(Doorway, VerticalDoorwayInAThickWall) {
  test::GridFixture f;
  f.draw({"##########", "#...##...#", "#........#", "#........#", "#...##...#", "##########"});
  const std::vector<Doorway> d = find(f);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_FALSE(d[0].alongX);
  EXPECT_EQ(d[0].first, (Cell{4, 2}));
  EXPECT_EQ(d[0].width, 2);
  EXPECT_EQ(d[0].depth, 2);
}

TEST(Doorway, CorridorsOpenAreasAndHolesAreNotDoorways) {
  test::GridFixture corridor;  // side walls run across every row: no jamb is a wall end
  corridor.draw({"#....#", "#....#", "#....#", "#....#"});
  EXPECT_TRUE(find(corridor).empty());
  test::GridFixture wide;  // an opening wider than a doorway
  wide.draw({"#..................#", "#..................#", "##................##", "#..................#"});
  EXPECT_TRUE(find(wide, DoorwayLimits{2, 15, 3, 1}).empty());
  test::GridFixture hole;  // a one-cell gap is a sensing hole
  hole.draw({"#.....#", "#.....#", "###.###", "#.....#"});
  EXPECT_TRUE(find(hole).empty());
  test::GridFixture unseen;  // the gap was never seen free
  unseen.draw({"#.....#", "#.....#", "##???##", "#.....#"});
  EXPECT_TRUE(find(unseen).empty());
}

TEST(Doorway, StrayCellsAreNoJambsWhenWallsMustGoOn) {
  test::GridFixture f;  // two stray occupied cells in the open (as noise leaves them), and a real doorway
  f.draw({"##########", "#........#", "#.#...#..#", "#........#", "####..####", "#........#"});
  EXPECT_EQ(find(f, DoorwayLimits{2, 15, 3, 1}).size(), 2u);  // the strays make a "doorway" too
  const std::vector<Doorway> d = find(f, DoorwayLimits{2, 15, 3, 2});
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].first, (Cell{4, 1}));
}

TEST(Doorway, SeveralDoorwaysOnOneWallAndACapacityLimit) {
  test::GridFixture f;
  f.draw({"#..........#", "#..........#", "#..##..##..#", "#..........#"});
  // Runs on the middle line: "..", "..", ".." between the jambs: the two outer ones end at the
  // side walls (not wall ends), the middle one lies between two wall ends.
  EXPECT_EQ(find(f).size(), 1u);
  test::GridFixture g;
  g.draw({"#...........#", "#...........#", "##..##..##..#", "#...........#"});
  Doorway out[1];
  bool more = false;
  EXPECT_EQ(findDoorways(g.grid(), g.grid().window(), DoorwayLimits{}, out, 1, &more), 1);
  EXPECT_TRUE(more);
}

TEST(RoomInterpretation, TwoExitsOnOneSideAndNoCrossSectionTakenForADoorway) {
  test::GridFixture f;
  // Two exits on the north wall, one on the south wall; the column between them spans the room
  // from wall to wall and is no doorway.
  f.draw({"???????????????", "?#.###.#######?", "?#...........#?", "?#...........#?", "?#...........#?",
          "?#####..######?", "??????#.#??????", "???????????????"});
  const RoomInterpretation r = interpretRoom(f.grid(), RoomLimits{3, 50});
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.interiorWidth(), 11);
  EXPECT_EQ(r.exitCount, 3);  // two on the north wall, one on the south wall
  int north = 0, south = 0;
  for (uint8_t i = 0; i < r.exitCount; ++i) {
    north += r.exits[i].side == Side::North;
    south += r.exits[i].side == Side::South;
  }
  EXPECT_EQ(north, 2);
  EXPECT_EQ(south, 1);
  EXPECT_EQ(r.freeCells, 33);
  EXPECT_EQ(r.partsX, 1);
  EXPECT_EQ(r.partsY, 1);
}

TEST(RoomInterpretation, InnerDoorwayOfANonRectangularRoom) {
  test::GridFixture f;
  // Two wall stubs leave a doorway between the room's lower and upper parts.
  f.draw(
      {"?##########?", "?#........#?", "?#........#?", "?###...####?", "?#........#?", "?#........#?", "?##########?"});
  const RoomInterpretation r = interpretRoom(f.grid(), RoomLimits{3, 50});
  ASSERT_TRUE(r.valid);
  ASSERT_EQ(r.exitCount, 1);
  EXPECT_EQ(r.exits[0].width, 3);
  EXPECT_EQ(r.exits[0].first, (Cell{4, 3}));
}

TEST(RoomInterpretation, AnOpenAreaLargerThanTheMaximumIsSeveralRooms) {
  test::GridFixture f;
  f.draw({"############", "#..........#", "#..........#", "#..........#", "############"});
  const RoomInterpretation r = interpretRoom(f.grid(), RoomLimits{2, 4});
  EXPECT_EQ(r.roomClass, RoomClass::TooLarge);
  EXPECT_EQ(r.partsX, 3);  // 10 cells wide, at most 4 per room
  EXPECT_EQ(r.partsY, 1);
}

}  // namespace
}  // namespace nxtmap
