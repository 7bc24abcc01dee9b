#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/explore/Propagation.hpp"
#include "host/mapping/MapScore.hpp"
#include "host/mapping/MappingRun.hpp"

namespace nxtmap {
namespace {

using P = Propagation;
using O = PropagationOutcome;

TEST(PropagationTable, TransitionsAsTheThesisListsThem) {
  const struct {
    P p;
    O o;
    P next;
  } table[] = {
      {P::ForwardRight, O::HitVertical, P::BackwardRight},  // wall in front
      {P::ForwardRight, O::HitHorizontal, P::ForwardLeft},  // wall on the right
      {P::ForwardRight, O::Corner, P::BackwardLeft},
      {P::ForwardLeft, O::HitVertical, P::BackwardLeft},  // (reading) see Propagation.hpp
      {P::ForwardLeft, O::HitHorizontal, P::ForwardRight},
      {P::ForwardLeft, O::Corner, P::BackwardRight},        // (reading)
      {P::BackwardRight, O::HitVertical, P::ForwardRight},  // wall at the back
      {P::BackwardRight, O::HitHorizontal, P::BackwardLeft},
      {P::BackwardRight, O::Corner, P::ForwardLeft},
      {P::BackwardLeft, O::HitVertical, P::ForwardLeft},
      {P::BackwardLeft, O::HitHorizontal, P::BackwardRight},
      {P::BackwardLeft, O::Corner, P::ForwardRight},
  };
  for (const auto& t : table) {
    EXPECT_EQ(nextPropagation(t.p, t.o), t.next) << propagationName(t.p) << " / " << outcomeName(t.o);
  }
}

struct Room {
  std::vector<std::string> rows;
  int col, row;
};

mapping::MappingRun runIn(const sim::World& w, int col, int row, mapping::Strategy s = mapping::Strategy::Propagation) {
  mapping::RunConfig c;
  c.startCol = col;
  c.startRow = row;
  c.noise = *sim::noiseProfileByName("none");
  c.strategy = s;
  return mapping::MappingRun(w, c);
}

std::vector<PropagationExplorer::Record> records(const mapping::MappingRun& run) {
  std::vector<PropagationExplorer::Record> out;
  const PropagationExplorer* p = run.propagation();
  for (uint16_t i = 0; i < p->recordCount(); ++i) out.push_back(p->record(i));
  return out;
}

// A square room: the start-up heuristic picks the open quadrant, the diagonal runs into the
// opposite corner (success), and the corner sends the robot into the opposite propagation.
TEST(Propagation, SquareRoomFromEachCornerStartsTowardsTheRoomAndEndsInTheFarCorner) {
  const sim::World w = sim::World::fromRows({"##########", "#........#", "#........#", "#........#", "#........#",
                                             "#........#", "#........#", "#........#", "#........#", "##########"});
  const struct {
    int col, row;
    P first;
  } starts[] = {{1, 8, P::ForwardRight}, {8, 8, P::ForwardLeft}, {1, 1, P::BackwardRight}, {8, 1, P::BackwardLeft}};
  for (const auto& s : starts) {
    mapping::MappingRun run = runIn(w, s.col, s.row);
    run.runToEnd();
    const auto log = records(run);
    ASSERT_GE(log.size(), 2u);
    EXPECT_EQ(log[0].propagation, s.first) << s.col << "," << s.row;
    EXPECT_EQ(log[0].outcome, O::Corner);
    EXPECT_EQ(std::abs(log[0].at.x), 7);
    EXPECT_EQ(std::abs(log[0].at.y), 7);
    EXPECT_EQ(log[1].propagation, nextPropagation(s.first, O::Corner));
  }
}

// Wall detection: in a wide room the forward-right diagonal meets the top wall, deviates along
// it, counts more than minWallCells blocked cells and fails with "wall ahead" -> backward-right.
TEST(Propagation, LongWallAheadIsAWall) {
  const sim::World w = sim::World::fromRows({"################", "#..............#", "#..............#",
                                             "#..............#", "#..............#", "################"});
  mapping::MappingRun run = runIn(w, 1, 4);
  run.runToEnd();
  const auto log = records(run);
  ASSERT_GE(log.size(), 2u);
  EXPECT_EQ(log[0].propagation, P::ForwardRight);
  EXPECT_EQ(log[0].outcome, O::HitVertical);
  EXPECT_EQ(log[1].propagation, P::BackwardRight);
}

TEST(Propagation, LongWallAsideIsAWall) {
  const sim::World w = sim::World::fromRows({"######", "#....#", "#....#", "#....#", "#....#", "#....#", "#....#",
                                             "#....#", "#....#", "#....#", "#....#", "#....#", "#....#", "######"});
  mapping::MappingRun run = runIn(w, 1, 12);
  run.runToEnd();
  const auto log = records(run);
  ASSERT_GE(log.size(), 2u);
  EXPECT_EQ(log[0].propagation, P::ForwardRight);
  EXPECT_EQ(log[0].outcome, O::HitHorizontal);
  EXPECT_EQ(log[1].propagation, P::ForwardLeft);
}

// A small obstacle on the diagonal is passed by a deviation, not taken for a wall.
TEST(Propagation, SmallObstacleIsPassedNotAWall) {
  const sim::World w = sim::World::fromRows({"############", "#..........#", "#..........#", "#..........#",
                                             "#..........#", "#..........#", "#....#.....#", "#..........#",
                                             "#..........#", "#..........#", "#..........#", "############"});
  mapping::MappingRun run = runIn(w, 1, 10);
  run.runToEnd();
  const auto log = records(run);
  ASSERT_GE(log.size(), 1u);
  EXPECT_EQ(log[0].propagation, P::ForwardRight);
  EXPECT_EQ(log[0].outcome, O::Corner) << "the diagonal went round the block to the far corner";
}

// Stop heuristic: the run stops propagating when a diagonal would be travelled again, then
// sweeps; the last propagation record says so.
TEST(Propagation, StopsWhenADiagonalPathWouldBeReused) {
  const sim::World w = sim::World::fromRows(
      {"########", "#......#", "#......#", "#......#", "#......#", "#......#", "#......#", "########"});
  mapping::MappingRun run = runIn(w, 1, 6);
  run.runToEnd();
  const auto log = records(run);
  ASSERT_FALSE(log.empty());
  bool reused = false;
  for (const auto& r : log) reused = reused || r.outcome == O::Reused;
  EXPECT_TRUE(reused);
  EXPECT_GE(run.propagation()->sweeps(), 1u);
  EXPECT_EQ(run.explorer().end(), ExplorerEnd::Complete);
}

// Both strategies, noise-free: every cell a reachable cell can see is mapped, none wrongly.
TEST(Explorers, MapEverythingObservableInSmallRooms) {
  const std::vector<Room> rooms = {
      {{"#######", "#.....#", "#.#.#.#", "#.....#", "#######"}, 1, 3},
      {{"##########", "#...#....#", "#...#....#", "#........#", "#...##...#", "#........#", "##########"}, 8, 5},
      {{"############", "#....#.....#", "#....#.....#", "#..........#", "######.#####", "#..........#", "#..........#",
        "############"},
       1,
       6},
      {{"#####", "#...#", "##.##", "#...#", "#####"}, 2, 1},
  };
  for (const mapping::Strategy s : {mapping::Strategy::Propagation, mapping::Strategy::Frontier}) {
    for (const Room& r : rooms) {
      const sim::World w = sim::World::fromRows(r.rows);
      mapping::MappingRun run = runIn(w, r.col, r.row, s);
      run.runToEnd();
      const mapping::MapScore score = mapping::scoreRun(run);
      EXPECT_EQ(run.explorer().end(), ExplorerEnd::Complete);
      EXPECT_EQ(score.wrongCells, 0) << mapping::strategyName(s) << " " << r.rows[1];
      EXPECT_EQ(score.unknownObservable, 0) << mapping::strategyName(s) << " " << r.rows[1];
      EXPECT_EQ(score.detectedOccupied, score.observableOccupied) << mapping::strategyName(s);
    }
  }
}

}  // namespace
}  // namespace nxtmap
