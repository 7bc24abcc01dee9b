#include <gtest/gtest.h>

#include "common/interpret/RoomInterpretation.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

struct InterpretCase {
  const char* name;
  std::vector<std::string> rows;  // '?' = never seen (beyond the walls)
  int exits;
  int interiorWidth, interiorHeight;
};

TEST(RoomInterpretation, WallsSizeAndExitsFromTable) {
  const std::vector<InterpretCase> cases = {
      {"closed room",
       {"??????????", "?########?", "?#......#?", "?#..##..#?", "?#......#?", "?########?", "??????????"},
       0,
       6,
       3},
      {"one exit", {"????..????", "?###..###?", "?#......#?", "?#......#?", "?########?"}, 1, 6, 2},
      {"two exits on one side", {"?#.###.#?", "?#.....#?", "?#.....#?", "?#######?"}, 2, 5, 2},
      {"three exits", {"???????", "##.####", "#.....#", "......#", "#.....#", "####.##", "???????"}, 3, 5, 3},
      {"five exits", {"#.#.####", "#......#", ".......#", "#.......", "#......#", "###.####"}, 5, 6, 4},
  };
  for (const InterpretCase& c : cases) {
    test::GridFixture f;
    f.draw(c.rows);
    const RoomInterpretation r = interpretRoom(f.grid());
    ASSERT_TRUE(r.valid) << c.name;
    EXPECT_EQ(r.exitCount, c.exits) << c.name;
    EXPECT_EQ(r.interiorWidth(), c.interiorWidth) << c.name;
    EXPECT_EQ(r.interiorHeight(), c.interiorHeight) << c.name;
  }
}

TEST(RoomInterpretation, ExitPositionAndWidth) {
  test::GridFixture f;
  f.draw({"??..??", "##..##", "#....#", "#....#", "#....#", "######"});
  const RoomInterpretation r = interpretRoom(f.grid(), RoomLimits{3, 50});
  ASSERT_TRUE(r.valid);
  ASSERT_EQ(r.exitCount, 1);
  EXPECT_EQ(r.exits[0].side, Side::North);
  EXPECT_EQ(r.exits[0].width, 2);
  EXPECT_EQ(r.exits[0].first.x, 2);
  EXPECT_EQ(r.exits[0].first.y, 4);
  EXPECT_EQ(r.wallLine[0], 4);
  EXPECT_EQ(r.wallLine[2], 0);
  EXPECT_EQ(r.roomClass, RoomClass::Room);
}

TEST(RoomInterpretation, RoomSizeLimits) {
  test::GridFixture f;
  f.draw({"#######", "#.....#", "#.....#", "#.....#", "#######"});
  EXPECT_EQ(interpretRoom(f.grid(), RoomLimits{3, 50}).roomClass, RoomClass::Room);
  EXPECT_EQ(interpretRoom(f.grid(), RoomLimits{4, 50}).roomClass, RoomClass::TooSmall);
  EXPECT_EQ(interpretRoom(f.grid(), RoomLimits{1, 4}).roomClass, RoomClass::TooLarge);
}

TEST(RoomInterpretation, EmptyMapIsNotARoom) {
  test::GridFixture f;
  EXPECT_FALSE(interpretRoom(f.grid()).valid);
  f.draw({"...", "..."});
  EXPECT_FALSE(interpretRoom(f.grid()).valid);
}

}  // namespace
}  // namespace nxtmap
