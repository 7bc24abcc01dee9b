// The inverse beam model on the brick's geometry (20 cm cells, sensor 6 cm ahead of the centre, 7..120 cm),
// expected cells worked out by hand: cell k's near face is 20 k - 16 cm from the sensor, its far face 20 k + 4.
// A 15 deg cone (262 mrad: tan 0.268, cos 0.966) covers a quarter of the side cells from 56 cm (k >= 4) and its
// arc is a cell wide from 37.3 cm; a 5 deg cone (87 mrad: tan 0.087) covers no side cell within 120 cm and its arc
// is a cell wide from 115 cm.
#include <gtest/gtest.h>

#include <string>

#include "common/sensing/BeamInverse.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

const RangeGeometry kBrick{20, 7, 120, 6};

char symbol(int weight) {
  switch (weight) {
    case -2: return 'F';
    case -1: return 'f';
    case 1: return 'o';
    case 2: return 'O';
    default: return '?';
  }
}

// The marks as one group of three per cell out (left, axis, right), '.' where nothing is marked.
std::string render(const RangeGeometry& g, int32_t coneMrad, RangeStatus status, int16_t cm) {
  RangeReading r;
  r.status = status;
  r.cm = cm;
  ConeMark marks[kMaxConeMarks];
  const int n = inverseBeam(g, coneMrad, r, marks, kMaxConeMarks);
  int farthest = 0;
  for (int i = 0; i < n; ++i) farthest = marks[i].along > farthest ? marks[i].along : farthest;
  std::string out;
  for (int k = 1; k <= farthest; ++k) {
    std::string cell = "...";
    for (int i = 0; i < n; ++i) {
      if (marks[i].along == k) cell[static_cast<size_t>(marks[i].side + 1)] = symbol(marks[i].weight);
    }
    out += (k > 1 ? " " : "") + cell;
  }
  return out;
}

TEST(BeamInverse, MarksFromTable) {
  const struct {
    const char* name;
    int32_t coneMrad;
    RangeStatus status;
    int16_t cm;
    const char* expected;
  } table[] = {
      {"near echo, narrow arc: the hit on the axis", 262, RangeStatus::Good, 30, ".F. .O."},
      {"far echo, wide cone: cells beside from k = 4, the arc shared", 262, RangeStatus::Good, 100,
       ".F. .F. .F. fFf .F. ooo"},
      {"far echo, narrow cone: the axis only", 87, RangeStatus::Good, 100, ".F. .F. .F. .F. .F. .O."},
      {"a far echo, narrow cone: its arc just reaches a cell (cell 7: near face 124 cm)", 87, RangeStatus::Good, 116,
       ".F. .F. .F. .F. .F. .F. ooo"},
      {"too far: free up to the range, beside where covered", 262, RangeStatus::TooFar, 0, ".F. .F. .F. fFf fFf"},
      {"no echo: the axis, weakly", 262, RangeStatus::NoEcho, 0, ".f. .f. .f. .f. .f."},
      {"too near: the adjacent cell", 262, RangeStatus::TooNear, 0, ".O."},
      {"inconsistent: nothing", 262, RangeStatus::Inconsistent, 0, ""},
  };
  for (const auto& t : table) EXPECT_EQ(render(kBrick, t.coneMrad, t.status, t.cm), t.expected) << t.name;
}

TEST(BeamInverse, TheEchoCellFollowsTheGeometry) {
  // Near faces at 4, 24, 44 ... cm: an echo is placed in the cell whose near face is within half a cell.
  EXPECT_EQ(render(kBrick, 0, RangeStatus::Good, 13), ".O.");
  EXPECT_EQ(render(kBrick, 0, RangeStatus::Good, 14), ".F. .O.");
  EXPECT_EQ(render(kBrick, 0, RangeStatus::Good, 33), ".F. .O.");
  EXPECT_EQ(render(kBrick, 0, RangeStatus::Good, 34), ".F. .F. .O.");
}

TEST(BeamInverse, AShortCapacityKeepsTheNearestCells) {
  RangeReading r;
  r.status = RangeStatus::Good;
  r.cm = 100;
  ConeMark marks[4];
  ASSERT_EQ(inverseBeam(kBrick, 262, r, marks, 4), 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(marks[i].along, i + 1);
  // The published geometry fits the capacity: 10 cm cells to 1 m, the widest cone.
  const RangeGeometry published{10, 5, 100, 0};
  ConeMark all[kMaxConeMarks];
  EXPECT_LT(inverseBeam(published, 600, r, all, kMaxConeMarks), kMaxConeMarks);
}

TEST(BeamInverse, MarksApplyToMapLayers) {
  test::GridFixture f;
  (void)f.map.markVisited(Cell{0, 0});
  RangeReading r;
  r.status = RangeStatus::Good;
  r.cm = 100;
  ConeMark marks[kMaxConeMarks];
  const int n = inverseBeam(kBrick, 262, r, marks, kMaxConeMarks);
  for (int i = 0; i < n; ++i) {
    const Cell c = coneCell(Cell{0, 0}, Dir::North, marks[i]);
    for (int k = 0; k < (marks[i].weight < 0 ? -marks[i].weight : marks[i].weight); ++k) {
      ASSERT_TRUE(marks[i].weight < 0 ? f.map.observeFree(c) : f.map.observeOccupied(c));
    }
  }
  const std::vector<std::string> expected = {"###", "?.?", "...", "?.?", "?.?", "?.?", "?.?"};
  EXPECT_EQ(test::picture(f.grid()), expected);
  EXPECT_EQ(f.map.evidence(Cell{0, 3}), -2);
  EXPECT_EQ(f.map.evidence(Cell{1, 4}), -1);
  EXPECT_EQ(f.map.evidence(Cell{-1, 6}), 1);
}

}  // namespace
}  // namespace nxtmap
