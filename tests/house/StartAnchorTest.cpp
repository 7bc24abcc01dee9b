// The start anchor: readings taken at the start (where the robot surely was) against the finished
// start room drawn as text ('#' wall, '.' free, ' ' unknown, 'S' the start cell, free); the map's
// whole-cell shift under which they fit again.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "DrawnMap.hpp"
#include "host/house/StartAnchor.hpp"

namespace nxtmap::house {
namespace {

// An echo from a wall face k cells away along d (10 cm cells), off by `errMm`.
AnchorReading wallAt(Dir d, int k, int errMm = 0) { return AnchorReading{d, 100 * k - 50 + errMm}; }

AnchorGeometry tenCentimetreCells() {
  AnchorGeometry g;
  g.cellMm = 100;
  g.reachCells = 25;
  g.wideFromMm = 570;
  return g;
}

struct Case {
  const char* what;
  std::vector<std::string> rows;
  std::vector<AnchorReading> readings;
  Cell expected;
};

const std::vector<std::string> kRoom = {
    "############", "#..........#", "#..........#", "#....S.....#", "#..........#", "############",
};

TEST(StartAnchor, FindsTheShiftUnderWhichTheStartReadingsFitAgain) {
  const std::vector<Case> cases = {
      {"the map as read at the start",
       kRoom,
       {wallAt(Dir::West, 5), wallAt(Dir::East, 6), wallAt(Dir::South, 2)},
       {0, 0}},
      {"within the tolerance", kRoom, {wallAt(Dir::West, 5, 25), wallAt(Dir::East, 6, -25)}, {0, 0}},
      {"mapped a cell east: the start is a cell east in the map",
       kRoom,
       {wallAt(Dir::West, 4), wallAt(Dir::East, 7)},
       {-1, 0}},
      {"one reading on the axis is enough", kRoom, {wallAt(Dir::East, 5)}, {1, 0}},
      {"both axes", kRoom, {wallAt(Dir::West, 6), wallAt(Dir::North, 2)}, {1, 1}},
      {"two cells", kRoom, {wallAt(Dir::West, 3)}, {-2, 0}},
      {"readings that disagree with each other: no shift fits them all",
       kRoom,
       {wallAt(Dir::West, 4), wallAt(Dir::East, 5)},
       {0, 0}},
      {"half a cell off: neither fits", kRoom, {wallAt(Dir::West, 5, 50)}, {0, 0}},
      {"more than two cells: beyond the shifts looked at", kRoom, {wallAt(Dir::West, 2)}, {0, 0}},
      {"no reading", kRoom, {}, {0, 0}},
      {"only a wall's cell would fit", {"#########", "#...#S..#", "#########"}, {wallAt(Dir::West, 4)}, {0, 0}},
      {"a corridor's end: either of two shifts would do, neither is taken",
       {"#########", "#...S...#", "#########", "         "},
       {wallAt(Dir::North, 2)},
       {0, 0}},
  };
  for (const Case& c : cases) {
    const test::DrawnRoom d = test::drawRoom(c.rows, "#", ".S", "S");
    const Cell shift = startAnchorShift(d.map, d.mark, c.readings, tenCentimetreCells());
    EXPECT_EQ(shift.x, c.expected.x) << c.what;
    EXPECT_EQ(shift.y, c.expected.y) << c.what;
  }
}

TEST(StartAnchor, AFarEchoMayComeFromTheLaneBesideTheAxis) {
  // The West wall has a notch on the start's row, a cell deeper than beside it. A far echo (beyond
  // the 57 cm from which the beam takes in the neighbouring lanes) comes from the nearer wall
  // beside the axis and fits as mapped; a near one cannot, and shows the notch's shift.
  const std::vector<std::string> rows = {
      " #..........", " #..........", "#.......S...", " #..........", " #..........",
  };
  const test::DrawnRoom d = test::drawRoom(rows, "#", ".S", "S");
  AnchorGeometry g = tenCentimetreCells();
  const Cell far = startAnchorShift(d.map, d.mark, {wallAt(Dir::West, 7)}, g);
  EXPECT_EQ(far.x, 0);
  g.wideFromMm = 1000;  // a narrow beam: only the axis lane
  const Cell narrow = startAnchorShift(d.map, d.mark, {wallAt(Dir::West, 7)}, g);
  EXPECT_EQ(narrow.x, -1);
}

}  // namespace
}  // namespace nxtmap::house
