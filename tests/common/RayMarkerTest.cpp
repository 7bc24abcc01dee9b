#include <gtest/gtest.h>

#include "common/sensing/RayMarker.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

// Marks one reading from (0,0) looking East with `g` (the published geometry unless given) and returns the
// row y = 0 from x = 0 to 11; `conclusive` receives what markRay said of the reading.
std::string markEast(RangeStatus status, int16_t cm, const std::vector<std::string>& before = {},
                     const RangeGeometry& g = RangeGeometry{10, 5, 100, 0}, bool trustBlind = false,
                     bool* conclusive = nullptr) {
  test::GridFixture f;
  if (!before.empty()) f.draw(before);
  (void)f.map.markVisited(Cell{0, 0});
  RangeReading r;
  r.status = status;
  r.cm = cm;
  const RayMarkResult m = markRay(f.map, g, Cell{0, 0}, Dir::East, r, trustBlind);
  if (conclusive != nullptr) *conclusive = m.conclusive;
  std::string row;
  for (int16_t x = 0; x <= 11; ++x) {
    const CellState st = f.map.at(Cell{x, 0});
    row += st == CellState::Free ? '.' : st == CellState::Occupied ? '#' : '?';
  }
  return row;
}

TEST(RayMarker, MarkingRulesFromTable) {
  const struct {
    const char* name;
    RangeStatus status;
    int16_t cm;
    const char* expected;
  } table[] = {
      {"echo: free before, occupied at the hit", RangeStatus::Good, 35, "....#???????"},
      {"echo two cells away", RangeStatus::Good, 15, "..#?????????"},
      {"echo at the far end", RangeStatus::Good, 95, "..........#?"},
      {"no echo: free up to the range", RangeStatus::NoEcho, 0, "..........??"},
      {"too far: free up to the range", RangeStatus::TooFar, 0, "..........??"},
      {"too near: the adjacent cell", RangeStatus::TooNear, 0, ".#??????????"},
      {"inconsistent: nothing", RangeStatus::Inconsistent, 0, ".???????????"},
  };
  for (const auto& t : table) EXPECT_EQ(markEast(t.status, t.cm), t.expected) << t.name;
}

// The same with a sensor blind below blindCm (mountCm 6 for the brick's 20 cm cells): the reading is always
// taken as said (conclusive), whatever it marks.
std::string markBlind(RangeStatus status, int16_t cm, const RangeGeometry& g, const std::string& before,
                      bool trustBlind) {
  bool conclusive = false;
  const std::string row =
      markEast(status, cm, before.empty() ? std::vector<std::string>{} : std::vector<std::string>{before}, g,
               trustBlind, &conclusive);
  EXPECT_TRUE(conclusive);
  return row;
}

TEST(RayMarker, NoEchoVouchesForNothingWhileTheBlindZoneIsUnknown) {
  const RangeGeometry published{10, 5, 100, 0, 0, 7};  // 10 cm cells, sensor at the centre, blind below 7 cm
  const RangeGeometry brick{20, 7, 120, 6, 0, 7};      // 20 cm cells, sensor 6 cm out: cell 1 from 4 cm
  const RangeGeometry deep{10, 5, 100, 0, 0, 16};      // blind to 16 cm: cells 1 and 2 (near faces 5, 15 cm)
  EXPECT_EQ(published.blindCells(), 1);
  EXPECT_EQ(brick.blindCells(), 1);
  EXPECT_EQ(deep.blindCells(), 2);
  EXPECT_EQ((RangeGeometry{10, 5, 100, 0, 0, 5}).blindCells(), 0);  // the near face at 5 cm is seen
  const struct {
    const char* name;
    RangeStatus status;
    int16_t cm;
    RangeGeometry g;
    const char* before;
    bool trust;
    const char* expected;
  } table[] = {
      {"no echo, adjacent cell unknown: nothing", RangeStatus::NoEcho, 0, published, "", false, ".???????????"},
      {"no echo, adjacent cell known free", RangeStatus::NoEcho, 0, published, "..", false, "..........??"},
      {"no echo where the robot was set down", RangeStatus::NoEcho, 0, published, "", true, "..........??"},
      {"no echo, a known wall in the blind zone", RangeStatus::NoEcho, 0, published, ".#", false, ".#??????????"},
      {"too far: an echo came back, nothing blind", RangeStatus::TooFar, 130, published, "", false, "..........??"},
      {"an echo is unchanged", RangeStatus::Good, 35, published, "", false, "....#???????"},
      {"brick: adjacent cell unknown", RangeStatus::NoEcho, 0, brick, "", false, ".???????????"},
      {"brick: adjacent cell known free", RangeStatus::NoEcho, 0, brick, "..", false, "......??????"},
      {"two blind cells, one known", RangeStatus::NoEcho, 0, deep, "..", false, "..??????????"},
      {"two blind cells, both known", RangeStatus::NoEcho, 0, deep, "...", false, "..........??"},
  };
  for (const auto& t : table) EXPECT_EQ(markBlind(t.status, t.cm, t.g, t.before, t.trust), t.expected) << t.name;
}

TEST(RayMarker, DoesNotReadThroughAKnownWall) {
  // A wall already known 3 cells away: a no-echo reading stops there (and weakens it once).
  const std::string row = markEast(RangeStatus::NoEcho, 0, {"...#"});
  EXPECT_EQ(row.substr(4), "????????");
}

TEST(RayMarker, StopsAtTheEdgeOfTheGridsCapacityAndSaysSo) {
  // A 32-cell grid already holding x = -25: only x up to 6 fits. A no-echo reading east from 0
  // marks free up to the edge, not beyond, and the reading still counts (conclusive).
  const struct {
    int16_t knownWest;  // the westmost cell already in the window
    const char* expected;
    bool clipped;
  } table[] = {
      {-21, "..........??", false},  // the range (10 cells) fits: x <= 10
      {-25, ".......?????", true},   // x <= 6 fits
      {-31, ".???????????", true},   // nothing east of the robot fits
  };
  for (const auto& t : table) {
    test::GridFixture f;
    (void)f.map.observeFree(Cell{t.knownWest, 0});
    (void)f.map.markVisited(Cell{0, 0});
    RangeReading r;
    r.status = RangeStatus::NoEcho;
    const RayMarkResult m = markRay(f.map, RangeGeometry{10, 5, 100, 0}, Cell{0, 0}, Dir::East, r);
    std::string row;
    for (int16_t x = 0; x <= 11; ++x) row += f.map.at(Cell{x, 0}) == CellState::Free ? '.' : '?';
    EXPECT_EQ(row, t.expected) << t.knownWest;
    EXPECT_EQ(m.clipped, t.clipped) << t.knownWest;
    EXPECT_TRUE(m.conclusive) << t.knownWest;
  }
}

TEST(RayMarker, ReadMemoryIsPerDirection) {
  test::GridFixture f;
  EXPECT_FALSE(f.map.wasRead(Cell{2, 3}, Dir::East));
  f.map.setRead(Cell{2, 3}, Dir::East);
  EXPECT_TRUE(f.map.wasRead(Cell{2, 3}, Dir::East));
  EXPECT_FALSE(f.map.wasRead(Cell{2, 3}, Dir::West));
  EXPECT_FALSE(f.map.wasRead(Cell{3, 3}, Dir::East));
}

TEST(MapLayers, EvidenceCorrectsAnIsolatedWrongHit) {
  test::GridFixture f;
  const Cell c{4, 0};
  ASSERT_TRUE(f.map.observeOccupied(c));
  EXPECT_EQ(f.map.at(c), CellState::Occupied);
  ASSERT_TRUE(f.map.observeFree(c));
  ASSERT_TRUE(f.map.observeFree(c));
  EXPECT_EQ(f.map.at(c), CellState::Free);
  ASSERT_TRUE(f.map.markVisited(Cell{5, 0}));
  ASSERT_TRUE(f.map.observeOccupied(Cell{5, 0}));
  EXPECT_EQ(f.map.at(Cell{5, 0}), CellState::Free) << "a cell the robot stood in stays free";
}

TEST(MapLayers, ABlockedMoveIsCertainUnlessTheCellIsSurelyFree) {
  struct Row {
    const char* before;
    int8_t evidence;  // after one blocked move
    CellState state;
  } rows[] = {
      {"unknown", 7, CellState::Occupied},
      {"seen free once", 7, CellState::Occupied},
      {"seen occupied once", 7, CellState::Occupied},
      {"stood in", -4, CellState::Free},  // as three echoes: still free
  };
  for (const Row& r : rows) {
    test::GridFixture f;
    const Cell c{3, 2};
    const std::string before = r.before;
    bool ok = true;
    if (before == "seen free once") ok = f.map.observeFree(c);
    if (before == "seen occupied once") ok = f.map.observeOccupied(c);
    if (before == "stood in") ok = f.map.markVisited(c);
    ASSERT_TRUE(ok) << r.before;
    ASSERT_TRUE(f.map.observeBlocked(c));
    EXPECT_EQ(f.map.evidence(c), r.evidence) << r.before;
    EXPECT_EQ(f.map.at(c), r.state) << r.before;
  }
  // Blocked a second time, a cell stood in is certain.
  test::GridFixture f;
  ASSERT_TRUE(f.map.markVisited(Cell{1, 1}));
  ASSERT_TRUE(f.map.observeBlocked(Cell{1, 1}));
  ASSERT_TRUE(f.map.observeBlocked(Cell{1, 1}));
  EXPECT_EQ(f.map.evidence(Cell{1, 1}), 7);
}

}  // namespace
}  // namespace nxtmap
