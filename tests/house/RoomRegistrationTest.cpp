// RoomRegistration: a room whose frame is believed a cell or two off is shifted back onto the rooms
// already mapped, from tables of small maps drawn as text ('#' wall, '.' free, ' ' unknown).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "DrawnMap.hpp"
#include "host/house/RoomRegistration.hpp"

namespace nxtmap::house {
namespace {

using test::drawMap;

// The room already mapped: a room 8 wide with a doorway in its top wall (house frame).
const std::vector<std::string> kKnown = {
    "##########", "#........#", "#........#", "#........#", "#........#", "###....###",
};

struct Case {
  const char* what;
  int beliefDx, beliefDy;  // how far off the believed frame is (house cells)
  int quarters;            // the new room's frame turned this many quarters clockwise
  int wantDx, wantDy;      // the shift expected back
};

class RoomRegistrationCases : public ::testing::TestWithParam<Case> {};

TEST_P(RoomRegistrationCases, ShiftsTheFrameBackOntoTheKnownRooms) {
  const Case& k = GetParam();
  const network::RoomMap known = drawMap(kKnown, 0, 0);  // house cells x 0..9, y 0..5
  // The new room saw the same walls: in the true frame its cells are the house cells themselves
  // (turned by `quarters`). The believed frame is off by (beliefDx, beliefDy).
  const network::RoomTransform truth = network::RoomTransform::fromParts(0, 0, k.quarters);
  const network::RoomTransform toTruth = truth.inverse();
  network::RoomMap fresh(-20, -20, 41, 41);
  for (int y = known.minY(); y <= known.maxY(); ++y) {
    for (int x = known.minX(); x <= known.maxX(); ++x) {
      const Cell h{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      if (known.at(h) != CellState::Unknown) fresh.set(toTruth.apply(h), known.at(h));
    }
  }
  const network::RoomTransform believed = network::RoomTransform::fromParts(k.beliefDx, k.beliefDy, k.quarters);
  const RoomRegistration r = registerRoom(fresh, believed, known, 2);
  EXPECT_EQ(r.dx, k.wantDx) << k.what;
  EXPECT_EQ(r.dy, k.wantDy) << k.what;
  EXPECT_EQ(r.toHouse, network::RoomTransform::fromParts(k.beliefDx + k.wantDx, k.beliefDy + k.wantDy, k.quarters))
      << k.what;
  if (r.shifted()) {
    EXPECT_GE(r.scoreAfter, r.scoreBefore + 48) << k.what;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, RoomRegistrationCases,
    ::testing::Values(Case{"on target", 0, 0, 0, 0, 0}, Case{"one cell east", 1, 0, 0, -1, 0},
                      Case{"a cell south and two west", -2, -1, 0, 2, 1},
                      Case{"turned a quarter, one north", 0, 1, 1, 0, -1},
                      Case{"turned a half, off diagonally", 1, 1, 2, -1, -1},
                      Case{"beyond the search: the two cells back it may go, where far fewer cells disagree", 3, 0, 0,
                           -2, 0}));

TEST(RoomRegistration, NoOverlapMeansNoChange) {
  const network::RoomMap known = drawMap(kKnown, 0, 0);
  const network::RoomMap fresh = drawMap({"#####", "#...#", "#####"}, 0, 0);
  const network::RoomTransform far = network::RoomTransform::fromParts(100, 100, 0);
  const RoomRegistration r = registerRoom(fresh, far, known, 2);
  EXPECT_FALSE(r.shifted());
  EXPECT_EQ(r.toHouse, far);
  EXPECT_EQ(r.scoreBefore, 0);
}

TEST(RoomRegistration, AFewCellsAboutADoorwayCannotMoveARoom) {
  // The new room saw only the doorway of the known room's top wall and the wall beside it, and its
  // frame is believed a cell west. The few cells fit better a cell east, but not by the margin:
  // a room is moved only on the evidence of many of its walls.
  const network::RoomMap known = drawMap(kKnown, 0, 0);
  const network::RoomMap fresh = drawMap({"  #....#  "}, 0, 0);
  const network::RoomTransform believed = network::RoomTransform::fromParts(-1, 0, 0);
  const RoomRegistration loose = registerRoom(fresh, believed, known, 2, 1, 0);
  EXPECT_EQ(loose.dx, 1);  // with almost no margin (and no conflict to resolve) it would move
  const RoomRegistration r = registerRoom(fresh, believed, known, 2);
  EXPECT_FALSE(r.shifted());
  EXPECT_EQ(r.toHouse, believed);
}

TEST(RoomRegistration, AWallMappedACellApartFromItsTwoSidesDoesNotMoveARoom) {
  // Two rooms side by side share a wall that lies on a cell boundary: the known room mapped it in its
  // row 3, the new room from below in row 4. Laid a row up, the new room's 20 wall cells would fall on
  // the known room's (well past the margin), but where the new room is nothing disagrees: it stays.
  const network::RoomMap known = drawMap(
      {"######################", "#....................#", "#....................#", "######################"}, 0, 0);
  const network::RoomMap fresh = drawMap({"######################", "#....................#", "#....................#",
                                          "#....................#", "######################"},
                                         0, 4);
  const network::RoomTransform believed = network::RoomTransform::fromParts(0, 0, 0);
  const RoomRegistration r = registerRoom(fresh, believed, known, 2);
  EXPECT_FALSE(r.shifted()) << r.dx << "," << r.dy;
  EXPECT_EQ(r.toHouse, believed);
  // A room that shares the known room's wall row (a wall inside a cell), believed a row too low, lays
  // its free cells on that wall and its wall on the known room's free cells: shifted back up.
  const network::RoomMap above = drawMap({"######################", "#....................#", "#....................#",
                                          "#....................#", "######################"},
                                         0, 3);
  const RoomRegistration low = registerRoom(above, network::RoomTransform::fromParts(0, -1, 0), known, 2);
  EXPECT_EQ(low.dy, 1);
  EXPECT_EQ(low.dx, 0);
}

}  // namespace
}  // namespace nxtmap::house
