// Walls anywhere (RangeGeometry::faceMarginCm, echoMarginCm): which cell an echo marks, how the pilot learns where the faces lie
// (FaceLines), and what that is worth in a room whose walls are not on the cells' edges.
#include <gtest/gtest.h>

#include <cstdio>

#include "common/motion/FaceLines.hpp"
#include "tests/common/PilotRoomRig.hpp"

namespace nxtmap {
namespace {

TEST(RangeGeometry, FacesAnywhereMarkTheCellHoldingTheFaceBroughtTheEchoMarginNearer) {
  RangeGeometry g{20, 7, 120, 6};  // the brick: 20 cm cells, sensors 6 cm ahead of the centre
  g.faceMarginCm = 3;
  g.echoMarginCm = 3;
  // The face is cm + 6 from the centre; cell k holds (k - 1/2) .. (k + 1/2) cells, less the echo margin (3 cm; the
  // brick's 1 cm; none).
  const struct {
    int16_t cm, published, anywhere, nearer1, exact;
  } table[] = {
      {4, 1, 1, 1, 1},    // 10 cm from the centre: the adjacent cell's near edge
      {7, 1, 1, 1, 1},    // 13 cm
      {23, 2, 1, 1, 1},   // 29 cm: in the adjacent cell (10..30 cm), which the published rule rounds to its far edge
      {24, 2, 1, 1, 2},   // 30 cm: on the edge of cell 2, which holds it, unless brought nearer
      {25, 2, 1, 2, 2},   // 31 cm, 1 cm into cell 2: within 3 cm, so the cell before it (a read too long is safe)
      {26, 2, 1, 2, 2},   // 32 cm, 2 cm into cell 2
      {27, 2, 2, 2, 2},   // 33 cm, less 3: the next cell's near edge
      {40, 3, 2, 2, 2},   // 46 cm: the far half of cell 2 (30..50 cm), rounded on to cell 3 by the published rule
      {110, 6, 6, 6, 6},  // 116 cm: cell 6 (110..130 cm) every way
  };
  for (const auto& t : table) {
    RangeGeometry published = g, nearer1 = g, exact = g;
    published.faceMarginCm = 0;
    nearer1.echoMarginCm = 1;
    exact.echoMarginCm = 0;
    EXPECT_EQ(published.hitCell(t.cm), t.published) << t.cm << " cm";
    EXPECT_EQ(g.hitCell(t.cm), t.anywhere) << t.cm << " cm";
    EXPECT_EQ(nearer1.hitCell(t.cm), t.nearer1) << t.cm << " cm";
    EXPECT_EQ(exact.hitCell(t.cm), t.exact) << t.cm << " cm";
    // Where the start's snap lays faces does not follow the echo margin: the adjacent cell's near edge plus twice
    // the face margin.
    EXPECT_EQ(exact.faceMm(1), 100 + 60);
  }
}

TEST(FaceLines, LearnsEachLinesFaceWeighingEveryReadingByHowWellItIsKnown) {
  FaceLines f;
  int32_t mm = 0, var = 0;
  EXPECT_FALSE(f.face(Cell{3, 5}, Dir::North, mm, var));
  // Each step: learn (pastEdgeMm, variance) for the face of row 5 seen looking north, then what is known.
  const struct {
    int32_t mm, var;
    bool learnt;
    int32_t knownMm, knownVar;
  } table[] = {
      {40, 400, true, 40, 400},     // the first reading is taken as it is
      {60, 400, true, 50, 200},     // as sure as what was known: half way, half the variance
      {120, 100, false, 50, 200},   // 70 mm off, past 30 mm and 3 sigma: another face (a leg before the wall)
      {44, 600, true, 48, 150},     // a less sure reading moves it less: by a quarter of 6 mm, rounded
      {5000, 1, false, 48, 150},    // far off and sure: refused
      {-20, 80000, true, 48, 149},  // very unsure (kept to 65535 mm^2): it hardly counts (48 - 68 * 150 / 65685)
  };
  for (const auto& t : table) {
    EXPECT_EQ(f.learn(Cell{3, 5}, Dir::North, t.mm, t.var), t.learnt) << t.mm;
    ASSERT_TRUE(f.face(Cell{3, 5}, Dir::North, mm, var));
    EXPECT_EQ(mm, t.knownMm) << t.mm;
    EXPECT_EQ(var, t.knownVar) << t.mm;
  }
  // A line is its row (looking north or south) or column (east or west), per direction, modulo 64 cells.
  EXPECT_TRUE(f.face(Cell{-40, 5}, Dir::North, mm, var));
  EXPECT_TRUE(f.face(Cell{3, 69}, Dir::North, mm, var));
  EXPECT_FALSE(f.face(Cell{3, 5}, Dir::South, mm, var));
  EXPECT_FALSE(f.face(Cell{5, 3}, Dir::East, mm, var));
  EXPECT_FALSE(f.learn(Cell{-1, -1}, Dir::West, 10, 0));  // a reading must come with its (positive) variance
  EXPECT_TRUE(f.learn(Cell{-1, -1}, Dir::West, -10, 50));
  EXPECT_TRUE(f.face(Cell{-1, 63}, Dir::West, mm, var));
  EXPECT_EQ(mm, -10);
  EXPECT_EQ(f.known(), 2);
  f.clear();
  EXPECT_EQ(f.known(), 0);
}

// A room 1.6 m x 1.6 m whose walls stand 12..41 mm past a cell edge (cells 100 mm), mapped by a pilot with noisy
// wheels and sonars, faces taken on the cells' edges (the published rule) and faces anywhere (learnt). Summed
// over runs: the learnt faces map fewer cells wrongly and know the robot's position better.
TEST(Pilot, LearntFacesMapARoomWhoseWallsAreOffTheCellEdgesBetter) {
  ExplorerConfig published;
  ExplorerConfig anywhere;
  anywhere.geometry.faceMarginCm = 2;
  anywhere.geometry.echoMarginCm = 1;
  int wrong[2] = {0, 0};
  double positionMm[2] = {0, 0};
  for (uint32_t run = 1; run <= 10; ++run) {
    const pilotrig::Wheels w = pilotrig::noisyWheels(20, 15, run);
    for (int k = 0; k < 2; ++k) {
      const pilotrig::RoomRun r =
          pilotrig::runInRoom(PilotConfig{}, -738, 862, -629, 991, w, k == 0 ? published : anywhere);
      ASSERT_GT(r.readings, 20);
      wrong[k] += r.wrongCells;
      positionMm[k] += r.meanEstimateErrorMm / 10;
    }
  }
  std::printf("wrong cells %d on edges, %d anywhere; position error %.1f mm on edges, %.1f anywhere\n", wrong[0],
              wrong[1], positionMm[0], positionMm[1]);
  EXPECT_LT(wrong[1] * 2, wrong[0]);
  EXPECT_LT(positionMm[1], positionMm[0]);
}

// A room whose four walls stand 15 mm past a cell edge (cells 100 mm): between the brick's echo margin (1 cm) and
// its face margin (here 2 cm). Brought the face margin nearer, every echo of a wall marks the cell before it, a
// wall on open floor all round; brought 1 cm nearer, the cell that holds it.
TEST(Pilot, AnEchoBroughtOnlyItsOwnMarginNearerMapsAFaceJustPastAnEdgeInItsCell) {
  ExplorerConfig echo1, echo2;
  echo1.geometry.faceMarginCm = echo2.geometry.faceMarginCm = 2;
  echo1.geometry.echoMarginCm = 1;
  echo2.geometry.echoMarginCm = 2;
  int wrong[2] = {0, 0};
  for (uint32_t run = 1; run <= 5; ++run) {
    const pilotrig::Wheels w = pilotrig::noisyWheels(20, 15, run);
    for (int k = 0; k < 2; ++k) {
      const pilotrig::RoomRun r = pilotrig::runInRoom(PilotConfig{}, -765, 865, -665, 965, w, k == 0 ? echo1 : echo2);
      ASSERT_GT(r.readings, 20);
      wrong[k] += r.wrongCells;
    }
  }
  std::printf("wrong cells %d with the echo 1 cm nearer, %d with it 2 cm nearer\n", wrong[0], wrong[1]);
  EXPECT_LT(wrong[0] * 2, wrong[1]);
}

}  // namespace
}  // namespace nxtmap
