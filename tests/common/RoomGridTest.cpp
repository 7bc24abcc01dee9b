#include <gtest/gtest.h>

#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

const std::vector<std::string> kRoom = {
    "######", "#....#", "#.#..#", "#....#", "######",
};

TEST(RoomGrid, StartsUnknownAndGrowsIntoAllFourQuadrants) {
  test::GridFixture f;
  EXPECT_EQ(f.grid().at(Cell{0, 0}), CellState::Unknown);
  const Cell cells[] = {{0, 0}, {-5, 3}, {7, -9}, {-12, -12}, {19, 19}};
  for (const Cell c : cells) ASSERT_TRUE(f.grid().set(c, CellState::Free)) << c.x << "," << c.y;
  for (const Cell c : cells) EXPECT_EQ(f.grid().at(c), CellState::Free);
  EXPECT_EQ(f.grid().at(Cell{1, 1}), CellState::Unknown);
  EXPECT_EQ(f.grid().window().width(), 32);
  EXPECT_EQ(f.grid().count(CellState::Free), 5);
}

TEST(RoomGrid, RefusesToGrowPastItsCapacityAndChangesNothing) {
  test::GridFixture f;
  ASSERT_TRUE(f.grid().set(Cell{-10, 0}, CellState::Occupied));
  ASSERT_TRUE(f.grid().set(Cell{21, 0}, CellState::Free));  // width 32: exactly the capacity
  EXPECT_FALSE(f.grid().fits(Cell{22, 0}));
  EXPECT_FALSE(f.grid().set(Cell{22, 0}, CellState::Free));
  EXPECT_FALSE(f.grid().set(Cell{-11, 5}, CellState::Free));
  EXPECT_EQ(f.grid().window().minX, -10);
  EXPECT_EQ(f.grid().window().maxX, 21);
  EXPECT_EQ(f.grid().at(Cell{-10, 0}), CellState::Occupied) << "wrapping never aliases";
}

TEST(RoomGrid, TwoBitsPerCell) { EXPECT_EQ(sizeof(MapStorage<64, 64>::grid), 1024u); }

// The same room seen from a start in each quadrant: restructuring moves the origin to the
// room's lower-left corner, so all four give the same non-negative picture.
TEST(RoomGrid, RestructuresFromEveryQuadrant) {
  const struct { int ox, oy; } starts[] = {{1, 1}, {4, 1}, {4, 3}, {1, 3}, {2, 2}};
  for (const auto& s : starts) {
    test::GridFixture f;
    f.draw(kRoom, s.ox, s.oy);
    const Bounds before = f.grid().window();
    EXPECT_EQ(before.minX, -s.ox);
    const Cell shift = f.map.restructure();
    EXPECT_EQ(shift.x, -s.ox);
    EXPECT_EQ(shift.y, -s.oy);
    const Bounds after = f.grid().window();
    EXPECT_EQ(after.minX, 0);
    EXPECT_EQ(after.minY, 0);
    EXPECT_EQ(after.width(), 6);
    EXPECT_EQ(after.height(), 5);
    EXPECT_EQ(test::picture(f.grid()), kRoom) << "start " << s.ox << "," << s.oy;
    EXPECT_EQ(f.grid().at(Cell{2, 2}), CellState::Occupied);
  }
}

TEST(RoomGrid, RestructureMovesEveryLayerTogether) {
  test::GridFixture f;
  f.draw(kRoom, 4, 3);
  f.map.setRead(Cell{-3, -2}, Dir::North);
  f.map.setDiagonalUsed(Cell{-3, -2}, 1, 1);
  f.map.restructure();
  EXPECT_TRUE(f.map.wasRead(Cell{1, 1}, Dir::North));
  EXPECT_TRUE(f.map.diagonalUsed(Cell{1, 1}, 1, 1));
  EXPECT_TRUE(f.map.diagonalUsed(Cell{2, 2}, -1, -1)) << "a diagonal is used in both directions";
}

// forget() leaves the window as it was; shrink() takes it to the cells still known, from any side, and
// what it gave up can be grown into again the other way.
TEST(RoomGrid, ForgottenCellsShrinkTheWindowToWhatIsStillKnown) {
  const struct {
    Cell forgotten[2];
    Bounds after;
  } cases[] = {
      {{{-10, 0}, {-10, 0}}, Bounds{-3, -2, 21, 4}},  // the west end
      {{{21, 0}, {-10, 0}}, Bounds{-3, -2, 0, 4}},    // both ends
      {{{0, 4}, {1, 1}}, Bounds{-10, -2, 21, 0}},     // the top row (and a cell not known at all)
  };
  for (const auto& k : cases) {
    test::GridFixture f;
    for (const Cell c : {Cell{-10, 0}, Cell{21, 0}, Cell{-3, -2}, Cell{0, 4}, Cell{0, 0}})
      ASSERT_TRUE(f.grid().set(c, CellState::Free));
    EXPECT_TRUE(f.grid().full());
    for (const Cell c : k.forgotten) f.grid().forget(c);
    EXPECT_EQ(f.grid().window().minX, -10) << "forget() alone keeps the window";
    f.grid().shrink();
    const Bounds w = f.grid().window();
    EXPECT_EQ(w.minX, k.after.minX);
    EXPECT_EQ(w.minY, k.after.minY);
    EXPECT_EQ(w.maxX, k.after.maxX);
    EXPECT_EQ(w.maxY, k.after.maxY);
    for (const Cell c : k.forgotten) EXPECT_EQ(f.grid().at(c), CellState::Unknown);
    EXPECT_EQ(f.grid().at(Cell{0, 0}), CellState::Free);
    EXPECT_EQ(f.grid().count(CellState::Free), 5 - (k.forgotten[0] == k.forgotten[1] ? 1 : 2) +
                                                    (k.forgotten[1] == Cell{1, 1} ? 1 : 0));
    const Cell grown{static_cast<int16_t>(w.minX + 31), 0};  // as wide as the capacity from the new west end
    EXPECT_TRUE(f.grid().set(grown, CellState::Occupied)) << "no aliasing after a shrink";
    EXPECT_EQ(f.grid().at(grown), CellState::Occupied);
    for (const Cell c : k.forgotten) {  // the torus slots of the forgotten cells, seen from the grown window
      for (const int16_t wrap : {int16_t{-32}, int16_t{32}}) {
        const Cell alias{static_cast<int16_t>(c.x + wrap), c.y};
        if (f.grid().window().contains(alias)) {
          EXPECT_EQ(f.grid().at(alias), CellState::Unknown);
        }
      }
    }
  }
}

TEST(RoomGrid, ForgettingACellClearsEveryLayer) {
  test::GridFixture f;
  f.draw(kRoom, 1, 1);
  f.map.setRead(Cell{1, 1}, Dir::East);
  f.map.setDiagonalUsed(Cell{1, 1}, 1, 1);
  f.map.forget(Cell{1, 1});
  EXPECT_EQ(f.map.at(Cell{1, 1}), CellState::Unknown);
  EXPECT_FALSE(f.map.wasRead(Cell{1, 1}, Dir::East));
  EXPECT_FALSE(f.map.diagonalUsed(Cell{1, 1}, 1, 1));
  ASSERT_TRUE(f.map.observeOccupied(Cell{1, 1}));
  EXPECT_EQ(f.map.evidence(Cell{1, 1}), 1) << "no evidence left from before";
}

}  // namespace
}  // namespace nxtmap
