#include <gtest/gtest.h>

#include "common/explore/TravelPlanner.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

struct PlanCase {
  const char* name;
  std::vector<std::string> rows;  // (0,0) = bottom-left cell
  Pose from;
  Cell to;
  int cost;  // moves + quarter turns; -1 = unreachable
};

TEST(TravelPlanner, CostsCountMovesAndTurns) {
  const std::vector<PlanCase> cases = {
      {"straight ahead", {"....."}, {{0, 0}, Dir::East}, {4, 0}, 4},
      {"straight behind: drives backwards, no turn", {"....."}, {{4, 0}, Dir::East}, {0, 0}, 4},
      {"one corner: one turn", {"....", "....", "...."}, {{0, 0}, Dir::North}, {3, 2}, 6},
      {"start on the wrong axis", {"....."}, {{0, 0}, Dir::North}, {3, 0}, 4},
      {"around a wall", {"...", ".#.", ".#.", ".#."}, {{0, 0}, Dir::North}, {2, 0}, 10},
      {"walled off", {".#."}, {{0, 0}, Dir::North}, {2, 0}, -1},
      {"start is goal", {"."}, {{0, 0}, Dir::North}, {0, 0}, 0},
  };
  for (const PlanCase& c : cases) {
    test::GridFixture f;
    f.draw(c.rows);
    TravelStorage<32, 32, 512> storage;
    TravelPlanner planner(storage.view(), 32, 32);
    int found = -1;
    ASSERT_TRUE(planner.search(f.grid(), c.from, [&](Cell cell, uint16_t cost) {
      if (cell == c.to) found = cost;
      return cell == c.to;
    })) << c.name;
    EXPECT_EQ(found, c.cost) << c.name;
    if (found > 0) {
      Route route;
      ASSERT_TRUE(planner.routeTo(f.grid(), c.to, static_cast<uint16_t>(found), route)) << c.name;
      Cell at = c.from.cell;
      while (!route.empty()) {
        at = advance(at, route.front());
        EXPECT_TRUE(f.grid().isFree(at)) << c.name;
        route.pop();
      }
      EXPECT_EQ(at, c.to) << c.name;
    }
  }
}

// A body that sweeps into the neighbouring cells turns only where its four neighbours are known free
// (ExplorerConfig::turnNeedsRoom); elsewhere it drives along its axis, forward or backward.
TEST(TravelPlanner, ABodyThatNeedsRoomTurnsOnlyWhereItsFourNeighboursAreFree) {
  struct RoomCase {
    const char* name;
    Pose from;
    Cell to;
    int costAnywhere, costWithRoom;  // -1 = unreachable
  };
  // A room of 5 x 3 free cells inside its walls: only the middle row's inner cells (2..4, 2) have room.
  const std::vector<std::string> rows = {"#######", "#.....#", "#.....#", "#.....#", "#######"};
  const std::vector<RoomCase> cases = {
      {"along its axis: no turn needed", {{1, 1}, Dir::North}, {1, 3}, 2, 2},
      {"beside the west wall it cannot leave its column", {{1, 1}, Dir::North}, {5, 1}, 5, -1},
      {"turns one cell on, where there is room", {{3, 1}, Dir::North}, {5, 2}, 4, 4},
      {"the row along the south wall only from its axis", {{3, 1}, Dir::East}, {5, 1}, 2, 2},
      {"the south row cannot be joined across", {{3, 3}, Dir::North}, {5, 1}, 5, -1},
      {"backwards along its axis", {{3, 2}, Dir::East}, {1, 2}, 2, 2},
      {"a corner cell: reached only along a line it need not turn on", {{4, 2}, Dir::North}, {5, 3}, 3, -1},
      {"the same corner from its column", {{5, 1}, Dir::North}, {5, 3}, 2, 2},
  };
  for (const bool room : {false, true}) {
    for (const RoomCase& c : cases) {
      test::GridFixture f;
      f.draw(rows);
      TravelStorage<32, 32, 512> storage;
      TravelPlanner planner(storage.view(), 32, 32);
      planner.setTurnNeedsRoom(room);
      int found = -1;
      ASSERT_TRUE(planner.search(f.grid(), c.from, [&](Cell cell, uint16_t cost) {
        if (cell == c.to) found = cost;
        return cell == c.to;
      })) << c.name;
      EXPECT_EQ(found, room ? c.costWithRoom : c.costAnywhere) << c.name << (room ? " (room)" : "");
      if (found <= 0) continue;
      // Every turn of the route is taken in a cell with room.
      Route route;
      ASSERT_TRUE(planner.routeTo(f.grid(), c.to, static_cast<uint16_t>(found), route)) << c.name;
      Cell at = c.from.cell;
      bool vertical = isVertical(c.from.heading);
      while (!route.empty()) {
        if (isVertical(route.front()) != vertical) {
          EXPECT_TRUE(!room || TravelPlanner::roomToTurn(f.grid(), at))
              << c.name << " turns at " << at.x << "," << at.y;
          vertical = !vertical;
        }
        at = advance(at, route.front());
        route.pop();
      }
      EXPECT_EQ(at, c.to) << c.name;
    }
  }
}

TEST(TravelPlanner, ReportsQueueOverflowInsteadOfOverrunning) {
  test::GridFixture f;
  f.draw({"..........", "..........", "..........", "..........", ".........."});
  TravelStorage<32, 32, 4> storage;
  TravelPlanner planner(storage.view(), 32, 32);
  EXPECT_FALSE(planner.search(f.grid(), Pose{{0, 0}, Dir::North}, [](Cell, uint16_t) { return false; }));
}

TEST(TravelPlanner, SlicedSearchVisitsTheSameCellsAtTheSameCosts) {
  test::GridFixture f;
  f.draw({"......", ".##.#.", "......", "#.#...", "......"});
  for (const uint16_t slice : {uint16_t{1}, uint16_t{3}, uint16_t{1000}}) {
    TravelStorage<32, 32, 512> a, b;
    TravelPlanner whole(a.view(), 32, 32), sliced(b.view(), 32, 32);
    std::vector<std::pair<Cell, uint16_t>> expected, got;
    const Pose from{{0, 0}, Dir::North};
    ASSERT_TRUE(whole.search(f.grid(), from, [&](Cell c, uint16_t cost) {
      expected.emplace_back(c, cost);
      return false;
    }));
    sliced.start(from);
    int calls = 0;
    auto visit = [&](Cell c, uint16_t cost) {
      got.emplace_back(c, cost);
      return false;
    };
    while (sliced.proceed(f.grid(), visit, slice) == TravelPlanner::Status::Running) ++calls;
    EXPECT_EQ(got, expected) << "slice " << slice;
    if (slice == 1) {
      EXPECT_GT(calls, static_cast<int>(expected.size()));  // one state per call
    }
    // The sliced search leaves the same labels behind: the same route comes out.
    Route ra, rb;
    const auto& last = expected.back();
    ASSERT_TRUE(whole.routeTo(f.grid(), last.first, last.second, ra));
    ASSERT_TRUE(sliced.routeTo(f.grid(), last.first, last.second, rb));
    ASSERT_EQ(ra.remaining(), rb.remaining());
    while (!ra.empty()) {
      EXPECT_EQ(ra.front(), rb.front());
      ra.pop();
      rb.pop();
    }
  }
}

// Where no turn is allowed (a turn stalled there before: setNoTurn) a cell's two axis states are not linked, and
// their costs may be 3 apart, the same modulo 3. The route must come from the one the search reached first.
TEST(TravelPlanner, ARouteToACellWithoutTurnsWalksBackToTheStart) {
  struct Cells final : CellSet {
    bool contains(Cell c) const override { return c == Cell{2, 0} || c == Cell{2, 1}; }
  } noTurn;
  test::GridFixture f;
  f.draw({"....", "....", "...."});
  TravelStorage<32, 32, 512> storage;
  TravelPlanner planner(storage.view(), 32, 32);
  planner.setNoTurn(&noTurn);
  const Pose from{{2, 0}, Dir::East};
  const Cell to{2, 1};  // east-west from a turn beside it: 5; north-south only from above: 8
  int found = -1;
  ASSERT_TRUE(planner.search(f.grid(), from, [&](Cell cell, uint16_t cost) {
    if (cell == to && found < 0) found = cost;
    return false;  // label every state
  }));
  ASSERT_EQ(found, 5);
  Route route;
  ASSERT_TRUE(planner.routeTo(f.grid(), to, 5, route));
  Cell at = from.cell;
  int moves = 0;
  while (!route.empty()) {
    at = advance(at, route.front());
    EXPECT_TRUE(f.grid().isFree(at));
    route.pop();
    ++moves;
  }
  EXPECT_EQ(at, to);
  EXPECT_EQ(moves, 3);  // and two turns, neither where turns are not allowed
}

}  // namespace
}  // namespace nxtmap
