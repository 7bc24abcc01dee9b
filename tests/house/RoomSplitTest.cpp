#include <gtest/gtest.h>

#include "host/house/RoomSplit.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap::house {
namespace {

TEST(RoomSplit, AnOpenAreaOverTheMaximumBecomesRoomsJoinedAtTheCut) {
  test::GridFixture f;
  // 12 x 3 interior with an obstacle on the cut line: two parts of 6 columns.
  f.draw({"##############", "#............#", "#.....#......#", "#............#", "##############"});
  const RoomInterpretation r = interpretRoom(f.grid(), RoomLimits{2, 7});
  ASSERT_EQ(r.roomClass, RoomClass::TooLarge);
  ASSERT_EQ(r.partsX, 2);
  const network::RoomMap whole = network::RoomMap::fromGrid(f.grid());
  const RoomParts p = splitRoom(whole, r);
  ASSERT_EQ(p.maps.size(), 2u);
  EXPECT_EQ(p.maps[0].minX(), 0);
  EXPECT_EQ(p.maps[0].maxX(), 6);  // the cut line x = 6 belongs to both parts
  EXPECT_EQ(p.maps[1].minX(), 6);
  EXPECT_EQ(p.maps[1].maxX(), 13);
  // The obstacle (6, 2) splits the cut line into two gateways of one free cell each.
  ASSERT_EQ(p.cuts.size(), 2u);
  for (const RoomParts::Cut& c : p.cuts) {
    EXPECT_EQ(c.partA, 0);
    EXPECT_EQ(c.partB, 1);
    ASSERT_EQ(c.cells.size(), 1u);
    EXPECT_EQ(c.cells[0].x, 6);
    EXPECT_TRUE(whole.isFree(c.cells[0]));
  }
  EXPECT_EQ(p.partOf(Cell{2, 2}), 0);
  EXPECT_EQ(p.partOf(Cell{10, 2}), 1);
  EXPECT_EQ(p.partOf(Cell{40, 2}), -1);
  // Within the limit: one room, the same map.
  const RoomParts one = splitRoom(whole, interpretRoom(f.grid(), RoomLimits{2, 20}));
  ASSERT_EQ(one.maps.size(), 1u);
  EXPECT_TRUE(one.maps[0] == whole);
  EXPECT_TRUE(one.cuts.empty());
}

}  // namespace
}  // namespace nxtmap::house
