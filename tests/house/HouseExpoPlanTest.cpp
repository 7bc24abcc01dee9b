#include <gtest/gtest.h>

#include "host/house/HouseExpoPlan.hpp"

namespace nxtmap::house {
namespace {

const std::string kDir = std::string(NXTMAP_SOURCE_DIR) + "/worlds/houseexpo/";

TEST(HouseExpoPlan, RasterisesTheOutlineWithInteriorWallsAsOneCellLines) {
  const HousePlanLoad l = loadHouseExpo(kDir + "1f99717550c31ae321ca2313edceedcc.json");
  ASSERT_TRUE(l.plan) << l.error;
  const HousePlan& p = *l.plan;
  EXPECT_EQ(p.id, "1f99717550c31ae321ca2313edceedcc");
  EXPECT_EQ(p.roomNum, 2);
  EXPECT_EQ(p.rooms.size(), 2u);
  // bbox 0.1 .. 6.4 x 0.1 .. 4.8 m at 0.1 m, one wall ring: 65 x 49 cells.
  EXPECT_EQ(p.world.width(), 65);
  EXPECT_EQ(p.world.height(), 49);
  EXPECT_DOUBLE_EQ(p.world.resolutionM(), 0.10);
  // The wall between kitchen and living room (x 2.88 .. 3.0 m) is one cell: col 29; its doorway
  // spans y 1.13 .. 2.35 m.
  const auto rowOf = [&](double y) { return p.world.height() - 1 - static_cast<int>((y - p.originYM) / 0.1); };
  EXPECT_TRUE(p.world.blocked(29, rowOf(0.5)));
  EXPECT_FALSE(p.world.blocked(28, rowOf(0.5)));
  EXPECT_FALSE(p.world.blocked(30, rowOf(0.5)));
  EXPECT_FALSE(p.world.blocked(29, rowOf(1.7)));
  // The border ring is wall.
  for (int c = 0; c < p.world.width(); ++c) EXPECT_TRUE(p.world.blocked(c, 0));
  int col = 0, row = 0;
  ASSERT_TRUE(defaultStart(p, col, row));
  EXPECT_FALSE(p.world.blocked(col, row));
}

TEST(HouseExpoPlan, AllShippedPlansLoad) {
  for (const char* f : {"1f99717550c31ae321ca2313edceedcc.json", "3a977bda0c177c31c8c64e8076562d5a.json",
                        "75555d2f4a69546c4c811f85bac572d9.json", "house_expo_room_0000.json",
                        "house_expo_room_1451.json"}) {
    const HousePlanLoad l = loadHouseExpo(kDir + f);
    ASSERT_TRUE(l.plan) << l.error;
    EXPECT_GE(l.plan->roomNum, 2) << f;
    EXPECT_LE(l.plan->world.width(), 128) << f;  // a house fits the host's room capacity
  }
}

TEST(HouseExpoPlan, BadInputGivesOneClearMessage) {
  EXPECT_NE(loadHouseExpo(kDir + "missing.json").error.find("cannot open"), std::string::npos);
  EXPECT_NE(parseHouseExpo("{", "x").error.find("not valid JSON"), std::string::npos);
  EXPECT_NE(parseHouseExpo("[1,2]", "x").error.find("expected a JSON object"), std::string::npos);
  EXPECT_NE(parseHouseExpo(R"({"verts": [[0,0],[1,0]]})", "x").error.find("at least 3"), std::string::npos);
  EXPECT_NE(parseHouseExpo(R"({"verts": [[0,0],[1,0],["a",1]]})", "x").error.find("[x, y]"), std::string::npos);
  EXPECT_NE(parseHouseExpo(R"({"verts": [[0,0],[1000,0],[0,1000]]})", "x").error.find("larger"), std::string::npos);
  EXPECT_NE(parseHouseExpo(R"({"verts": [[0,0],[1,0],[0,1]], "room_category": {"K": [[0,0,1]]}})", "x")
                .error.find("[x1, y1, x2, y2]"),
            std::string::npos);
  EXPECT_TRUE(parseHouseExpo(R"({"verts": [[0,0],[1,0],[1,1],[0,1]]})", "x").plan.has_value());
}

}  // namespace
}  // namespace nxtmap::house
