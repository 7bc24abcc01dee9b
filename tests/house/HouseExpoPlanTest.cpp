#include <gtest/gtest.h>

#include <cmath>
#include <ctime>
#include <functional>
#include <sstream>
#include <vector>

#include "host/house/HouseExpoPlan.hpp"
#include "tests/support/TempDir.hpp"

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
  for (const char* f :
       {"1f99717550c31ae321ca2313edceedcc.json", "3a977bda0c177c31c8c64e8076562d5a.json",
        "75555d2f4a69546c4c811f85bac572d9.json", "house_expo_room_0000.json", "house_expo_room_1451.json"}) {
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

std::string pointList(const std::vector<std::pair<double, double>>& points) {
  std::ostringstream o;
  o.precision(17);
  o << "[";
  for (size_t i = 0; i < points.size(); ++i)
    o << (i ? "," : "") << "[" << points[i].first << "," << points[i].second << "]";
  return o.str() + "]";
}

// A circle of `n` outline points, radius r metres, centred at (r + 1, r + 1).
std::string circlePlan(int n, double r) {
  std::vector<std::pair<double, double>> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    points.emplace_back(r + 1.0 + r * std::cos(a), r + 1.0 + r * std::sin(a));
  }
  return R"({"id": "circle", "verts": )" + pointList(points) + "}";
}

// The CPU seconds `work` takes (not the wall clock: other builds and tests may share the machine).
double secondsFor(const std::function<void()>& work) {
  const std::clock_t t0 = std::clock();
  work();
  return static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
}

// Numbers and sizes no floor plan has: one message naming the field, never a crash, a wrapped
// number or minutes of work.
TEST(HouseExpoPlan, HostilePlansGiveOneClearMessage) {
  const std::string square = R"("verts": [[0,0],[4,0],[4,4],[0,4]])";
  struct Case {
    std::string json, message;
  };
  const std::vector<Case> cases = {
      {R"({"verts": [[0,0],[1e400,0],[0,1]]})", "not valid JSON"},
      {R"({"verts": [[1e308,1e308],[1e308,1e308],[1e308,1e308]]})", "within -1000..1000 m"},
      {R"({"verts": [[-1.7e308,0],[1.7e308,0],[0,1]]})", "within -1000..1000 m"},
      {R"({"verts": [[0,0],[1000.5,0],[0,1]]})", "within -1000..1000 m"},
      {R"({"verts": [[0,0],[150,0],[150,150],[0,150]]})", "the plan is 150 x 150 m, larger than 100 m a side"},
      {R"({"verts": [[0,0],[1,0],[2,0]]})", "the outline encloses no cell"},
      {"{" + square + R"(, "room_category": {"K": [[-1e300, 0, 1, 1]]}})", "room_category 'K' holds a box that is not"},
      {"{" + square + R"(, "room_category": {"K": [[0, 0, 1, 1e300]]}})", "within -1000..1000 m"},
      {"{" + square + R"(, "room_category": {"K": [[500, 500, 600, 600]]}})",
       "room_category 'K' holds a box [500, 500, 600, 600] that lies outside the outline"},
      {"{" + square + R"(, "room_category": {"K": [[0,0,1,1])" +
           [] {
             std::string more;
             for (int i = 0; i < 256; ++i) more += ",[0,0,1,1]";
             return more;
           }() +
           "]}}",
       "'room_category' holds more than 256 boxes"},
      {"{" + square + R"(, "room_category": {"K\nformat: x": [[0, 0, 1, 1]]}})", "room_category names must be 1..48"},
      {"{" + square + R"(, "room_category": {"NULL": [[0, 0, 1, 1]]}})", "room_category names must be 1..48"},
      {"{" + square + R"(, "id": "a\u001b[2Jb"})", "'id' must be a string of 1..128 printable characters"},
      {"{" + square + R"(, "id": 7})", "'id' must be a string"},
      {"{" + square + R"(, "room_num": -5})", "'room_num' must be a whole number in 0..256"},
      {"{" + square + R"(, "room_num": 9223372036854775807})", "'room_num' must be a whole number in 0..256"},
      {"{" + square + R"(, "room_num": 2.5})", "'room_num'"},
  };
  for (const Case& c : cases) {
    const HousePlanLoad l = parseHouseExpo(c.json, "x");
    EXPECT_FALSE(l.plan) << c.message;
    EXPECT_NE(l.error.find(c.message), std::string::npos) << l.error;
    EXPECT_EQ(l.error.find('\n'), std::string::npos) << l.error;
  }
  EXPECT_TRUE(parseHouseExpo("{" + square + R"(, "room_num": 3, "room_category": {"K": [[-3, -1, 2, 2]]}})", "x").plan);
}

TEST(HouseExpoPlan, OutlineSizeIsBoundedAndRasterisingScales) {
  // 20,000 points (once 20 CPU minutes): refused at once.
  const std::string many = circlePlan(20000, 5.0), most = circlePlan(static_cast<int>(kMaxPlanPoints), 20.0);
  double seconds = secondsFor([&] {
    const HousePlanLoad l = parseHouseExpo(many, "x");
    EXPECT_FALSE(l.plan);
    EXPECT_NE(l.error.find("'verts' holds 20000 points, more than 4096"), std::string::npos) << l.error;
  });
  EXPECT_LT(seconds, 0.5);
  // The most points accepted, over a 40 m circle (402 x 402 cells): quick, and the area right.
  seconds = secondsFor([&] {
    const HousePlanLoad l = parseHouseExpo(most, "x");
    ASSERT_TRUE(l.plan) << l.error;
    const sim::World& w = l.plan->world;
    int freeCells = 0;
    for (int r = 0; r < w.height(); ++r) {
      for (int c = 0; c < w.width(); ++c) freeCells += w.blocked(c, r) ? 0 : 1;
    }
    EXPECT_NEAR(freeCells, M_PI * 200.0 * 200.0, 200.0);  // pi r^2 in 0.1 m cells, within a cell a side
  });
  EXPECT_LT(seconds, 1.0);
}

TEST(HouseExpoPlan, OnlyRegularFilesOfBoundedSizeAreRead) {
  test::TempDir t("houseexpo_files");
  EXPECT_NE(loadHouseExpo(t.path()).error.find("is a directory"), std::string::npos);
  const std::string big = t.write(
      "big.json", R"({"verts": [[0,0],[1,0],[1,1],[0,1]], "pad": ")" + std::string(kMaxPlanFileBytes, 'x') + "\"}");
  const std::string bigError = loadHouseExpo(big).error;
  EXPECT_NE(bigError.find("larger than 1 MiB, the largest HouseExpo plan accepted"), std::string::npos) << bigError;
  EXPECT_NE(loadHouseExpo("/dev/zero").error.find("not a regular file"), std::string::npos);
}

}  // namespace
}  // namespace nxtmap::house
