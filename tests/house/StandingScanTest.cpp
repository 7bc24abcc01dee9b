// Where a lost robot really stands: readings taken in four directions, matched against small maps
// drawn as text ('#' wall, '.' free, ' ' unknown, 'B' the believed cell, free) at whole-cell shifts.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "DrawnMap.hpp"
#include "host/house/StandingScan.hpp"

namespace nxtmap::house {
namespace {

test::DrawnRoom draw(const std::vector<std::string>& rows) { return test::drawRoom(rows, "#", ".B", "B"); }

RangeGeometry tenCentimetreCells() {
  RangeGeometry g;
  g.cellCm = 10;
  g.maxCm = 100;
  return g;
}

// An echo from a wall k cells away: its near face is (k - 1/2) cells from the cell's centre.
StandingReading wallAt(Dir d, int k) { return StandingReading{d, true, 10 * k - 5}; }
StandingReading nothing(Dir d) { return StandingReading{d, false, 0}; }

const std::vector<std::string> kRoom = {
    "##########", "#........#", "#........#", "#...B....#", "#........#", "##########",
};

struct Case {
  const char* what;
  std::vector<std::string> rows;
  std::vector<StandingReading> readings;
  bool blockedNorth;
  Cell expected;
};

TEST(StandingScan, FindsTheWholeCellShiftThatExplainsTheReadings) {
  const std::vector<Case> cases = {
      {"readings that fit the believed cell",
       kRoom,
       {wallAt(Dir::North, 3), wallAt(Dir::East, 5), wallAt(Dir::South, 2), wallAt(Dir::West, 4)},
       false,
       Cell{0, 0}},
      {"truly one cell east",
       kRoom,
       {wallAt(Dir::North, 3), wallAt(Dir::East, 4), wallAt(Dir::South, 2), wallAt(Dir::West, 5)},
       false,
       Cell{1, 0}},
      {"truly two cells west and one south",
       kRoom,
       {wallAt(Dir::North, 4), wallAt(Dir::East, 7), wallAt(Dir::South, 1), wallAt(Dir::West, 2)},
       false,
       Cell{-2, -1}},
      {"only the walls across a corridor are seen: no shift along it can be told",
       {"#################################", "#...............B...............#", "#################################"},
       {wallAt(Dir::North, 1), nothing(Dir::East), wallAt(Dir::South, 1), nothing(Dir::West)},
       false,
       Cell{0, 0}},
      {"one echo a cell short is not enough to move", kRoom, {wallAt(Dir::East, 4)}, false, Cell{0, 0}},
      {"the robot stands on a cell the map knows free, never in unknown space",
       {"   #####", "   #.B.#", "   #####"},
       {wallAt(Dir::North, 1), wallAt(Dir::South, 1), wallAt(Dir::East, 2)},
       false,
       Cell{0, 0}},
      {"blocked driving north, with a wall just ahead: truly below the north wall",
       {"#####", "#...#", "#...#", "#.B.#", "#...#", "#####"},
       {wallAt(Dir::North, 1)},
       true,
       Cell{0, 2}},
  };
  const RangeGeometry g = tenCentimetreCells();
  for (const Case& c : cases) {
    const test::DrawnRoom d = draw(c.rows);
    const Dir north = Dir::North;
    const Cell shift = bestStandingShift(d.map, d.mark, c.readings, g, 100, c.blockedNorth ? &north : nullptr);
    EXPECT_EQ(shift.x, c.expected.x) << c.what;
    EXPECT_EQ(shift.y, c.expected.y) << c.what;
  }
}

TEST(StandingScan, AWallCellIsNeverWhereTheRobotStands) {
  const test::DrawnRoom d = draw({"#####", "#.B.#", "#####"});
  const RangeGeometry g = tenCentimetreCells();
  const std::vector<StandingReading> readings = {wallAt(Dir::North, 1), wallAt(Dir::South, 1)};
  EXPECT_GT(standingScore(d.map, d.mark, readings, g, 100, nullptr),
            standingScore(d.map, Cell{2, 2}, readings, g, 100, nullptr));
  EXPECT_LT(standingScore(d.map, Cell{0, 1}, readings, g, 100, nullptr), -1000);
}

TEST(StandingScan, ScoresEchoesAgainstTheFirstKnownWallAlongTheBeam) {
  const test::DrawnRoom d = draw({"#######", "#..B..#", "#######"});
  const RangeGeometry g = tenCentimetreCells();
  struct Row {
    const char* what;
    StandingReading reading;
    int expected;
  };
  const std::vector<Row> rows = {
      {"an echo on the wall", wallAt(Dir::East, 3), 2},
      {"an echo one cell short of the wall", wallAt(Dir::East, 2), 1},
      {"an echo beyond a known wall (the beam passed through it)", wallAt(Dir::East, 5), -2},
      {"nothing, with a wall well within reach", nothing(Dir::East), -2},
      {"nothing, with the wall adjacent", nothing(Dir::North), -2},
  };
  for (const Row& r : rows) {
    EXPECT_EQ(standingScore(d.map, d.mark, {r.reading}, g, 100, nullptr), r.expected) << r.what;
  }
}

}  // namespace
}  // namespace nxtmap::house
