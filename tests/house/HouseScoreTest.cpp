// HouseScore: a one-room house mapped with known mistakes, each row a map drawn as text against the same world
// ('#' occupied, '.' free, ' ' unknown): the counts of agreeing, unknown and wrong cells, and of the wrong ones how
// many are walls laid on open floor and how many obstacles held free.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/house/HouseScore.hpp"
#include "host/network/HouseNetwork.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::house {
namespace {

// A 6 x 5 room with a pillar; the robot starts at column 2, row 2 (every free cell is reachable).
const std::vector<std::string> kWorld = {
    "######", "#....#", "#..#.#", "#....#", "######",
};
constexpr int kStartCol = 2, kStartRow = 2;

// The map drawn in world cells, put into the house frame (room 0's frame: origin at the start, +y north).
network::RoomMap mapOf(const std::vector<std::string>& rows, const mapping::FrameTransform& f) {
  network::RoomMap m(-10, -10, 21, 21);
  for (int row = 0; row < static_cast<int>(rows.size()); ++row) {
    for (int col = 0; col < static_cast<int>(rows[static_cast<size_t>(row)].size()); ++col) {
      const char c = rows[static_cast<size_t>(row)][static_cast<size_t>(col)];
      if (c != ' ') m.set(f.toExplorer(col, row), c == '#' ? CellState::Occupied : CellState::Free);
    }
  }
  return m;
}

struct Case {
  const char* what;
  std::vector<std::string> map;
  int agree, unknown, wrong, wallsOnFloor;
};

class HouseScoreCases : public ::testing::TestWithParam<Case> {};

TEST_P(HouseScoreCases, CountsEachKindOfCell) {
  const Case& k = GetParam();
  const sim::World world = sim::World::fromRows(kWorld);
  const mapping::FrameTransform f(kStartCol, kStartRow, sim::Heading::N);
  network::HouseNetwork house;
  house.addRoom({"room0", mapOf(k.map, f), {}, {}});
  const HouseInWorld h{&house, &world, f, kStartCol, kStartRow, RangeGeometry{}};
  const HouseScore s = scoreHouse(h);
  EXPECT_EQ(s.observable, s.agree + s.unknown + s.wrong) << k.what;
  EXPECT_EQ(s.agree, k.agree) << k.what;
  EXPECT_EQ(s.unknown, k.unknown) << k.what;
  EXPECT_EQ(s.wrong, k.wrong) << k.what;
  EXPECT_EQ(s.wallsOnFloor, k.wallsOnFloor) << k.what;
  EXPECT_EQ(s.rooms, 1) << k.what;
}

// The world has 30 cells: 18 walls, 1 pillar, 11 free; 26 of them observable (the published reach is along the
// axes: no free cell sees the four corners).
INSTANTIATE_TEST_SUITE_P(
    Table, HouseScoreCases,
    ::testing::Values(Case{"exact", {"######", "#....#", "#..#.#", "#....#", "######"}, 26, 0, 0, 0},
                      Case{"nothing mapped", {}, 0, 26, 0, 0},
                      Case{"the pillar held free", {"######", "#....#", "#....#", "#....#", "######"}, 25, 0, 1, 0},
                      Case{"the east wall mapped a cell in",
                           {"######", "#...##", "#..###", "#...##", "######"},
                           23,
                           0,
                           3,
                           3},
                      Case{"both at once, a wall cell unknown",
                           {"#### #", "#...##", "#....#", "#....#", "######"},
                           23,
                           1,
                           2,
                           1}));

}  // namespace
}  // namespace nxtmap::house
