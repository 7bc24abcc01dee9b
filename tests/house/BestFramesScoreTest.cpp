// BestFramesScore: a two-room house whose second room was joined a few cells off is scored as if
// joined right, the move back reported, the house itself untouched; a room beyond reach of the moves
// scores lower. A small world drawn as text ('#' wall), the rooms' maps copied from it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/house/BestFramesScore.hpp"
#include "host/network/HouseNetwork.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::house {
namespace {

// Two rooms joined by a doorway in column 7; the right one holds a pillar. Start at column 3, row 4.
const std::vector<std::string> kWorld = {
    "################", "#......#.......#", "#......#.......#", "#..............#",
    "#......#...##..#", "#......#.......#", "#......#.......#", "################",
};
constexpr int kStartCol = 3, kStartRow = 4;
constexpr int kSplitCol = 7;  // room 0 holds columns 0..7, room 1 columns 7..15

// Room `cols` of the world, as seen from a frame whose origin is house cell `origin`.
network::RoomMap roomOf(const sim::World& w, const mapping::FrameTransform& f, int col0, int col1, Cell origin) {
  network::RoomMap m(-20, -20, 41, 41);
  for (int row = 0; row < w.height(); ++row) {
    for (int col = col0; col <= col1; ++col) {
      const Cell h = f.toExplorer(col, row);
      const Cell c{static_cast<int16_t>(h.x - origin.x), static_cast<int16_t>(h.y - origin.y)};
      m.set(c, w.blocked(col, row) ? CellState::Occupied : CellState::Free);
    }
  }
  return m;
}

struct Case {
  const char* what;
  int offX, offY;    // how far off room 1 was joined (house cells)
  int wantX, wantY;  // the move reported back
  bool perfect;      // scores as the house joined right
};

class BestFramesScoreCases : public ::testing::TestWithParam<Case> {};

TEST_P(BestFramesScoreCases, ScoresTheRoomsAtTheirBestFrames) {
  const Case& k = GetParam();
  const sim::World world = sim::World::fromRows(kWorld);
  const mapping::FrameTransform f(kStartCol, kStartRow, sim::Heading::N);
  const Cell origin1 = f.toExplorer(kSplitCol + 1, kStartRow);  // room 1's entrance
  network::HouseNetwork joined;
  joined.addRoom({"room0", roomOf(world, f, 0, kSplitCol, Cell{0, 0}), {}, {}});
  joined.addRoom({"room1",
                  roomOf(world, f, kSplitCol, world.width() - 1, origin1),
                  network::RoomTransform::fromParts(origin1.x, origin1.y, 0),
                  {}});
  network::HouseNetwork off = joined;
  off.rooms()[1].toHouse = network::RoomTransform::fromParts(origin1.x + k.offX, origin1.y + k.offY, 0);
  const HouseInWorld right{&joined, &world, f, kStartCol, kStartRow, RangeGeometry{}};
  HouseInWorld offView = right;
  offView.network = &off;

  const BestFramesScore b = scoreWithBestFrames(offView, 2);
  const HouseScore best = scoreHouse(right), raw = scoreHouse(offView);
  ASSERT_EQ(b.shifts.size(), 2u);
  EXPECT_EQ(b.shifts[0], (Cell{0, 0})) << k.what;
  EXPECT_EQ(b.shifts[1], (Cell{static_cast<int16_t>(k.wantX), static_cast<int16_t>(k.wantY)})) << k.what;
  EXPECT_EQ(b.score.agree == best.agree, k.perfect) << k.what << ": " << b.score.agree << " of " << best.agree;
  EXPECT_GE(b.score.agree, raw.agree) << k.what;
  EXPECT_GE(b.passes, 1) << k.what;
  EXPECT_LE(b.passes, BestFramesScore::kMaxPasses) << k.what;
  EXPECT_EQ(off.rooms()[1].toHouse, network::RoomTransform::fromParts(origin1.x + k.offX, origin1.y + k.offY, 0))
      << k.what << ": the house itself is not moved";
}

INSTANTIATE_TEST_SUITE_P(Table, BestFramesScoreCases,
                         ::testing::Values(Case{"joined right", 0, 0, 0, 0, true},
                                           Case{"a cell east", 1, 0, -1, 0, true},
                                           Case{"two west, a cell north", -2, 1, 2, -1, true},
                                           Case{"two south", 0, -2, 0, 2, true},
                                           Case{"three east: beyond the moves", 3, 0, -2, 0, false}));

TEST(BestFramesScore, AnEmptyHouseScoresAsItIs) {
  const sim::World world = sim::World::fromRows(kWorld);
  const network::HouseNetwork none;
  const HouseInWorld h{&none,     &world,    mapping::FrameTransform(kStartCol, kStartRow, sim::Heading::N),
                       kStartCol, kStartRow, RangeGeometry{}};
  const BestFramesScore b = scoreWithBestFrames(h);
  EXPECT_TRUE(b.shifts.empty());
  EXPECT_EQ(b.score.agree, 0);
  EXPECT_EQ(b.score.observable, scoreHouse(h).observable);
  EXPECT_EQ(b.passes, 1);
}

}  // namespace
}  // namespace nxtmap::house
