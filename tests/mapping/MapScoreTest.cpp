// Scoring hand-made maps against a scene: safety counts, the lost flag and the aligned score.
#include "host/mapping/MapScore.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/mapping/MapAlignment.hpp"
#include "host/sim/TruthRaster.hpp"

namespace nxtmap::mapping {
namespace {

using sim::Vec2;

// A 200 x 140 cm room with a 40 x 20 cm cupboard, a triangular stand and a table leg, the robot's grid of
// 10 cm cells through the start point (a cell centre) turned by headingDeg.
struct Room {
  explicit Room(double headingDeg = 0.0)
      : scene(makeScene()),
        place(sim::placeOnGrid(scene, Vec2(25, 25), headingDeg, 10.0)),
        truth(sim::rasterizeScene(scene, place.frame, place.width, place.height, "room")) {}
  static sim::Scene makeScene() {
    sim::Scene s;
    s.addRing(sim::Ring{{Vec2(0, 0), Vec2(200, 0), Vec2(200, 140), Vec2(0, 140)}});
    s.addRing(sim::Ring{{Vec2(120, 80), Vec2(160, 80), Vec2(160, 100), Vec2(120, 100)}});
    s.addRing(sim::Ring{{Vec2(60, 110), Vec2(90, 125), Vec2(55, 130)}});
    s.addDisc(sim::Disc{Vec2(70, 55), 1.5});
    s.finish();
    return s;
  }
  sim::Scene scene;
  sim::Placement place;
  sim::World truth;
};

// What a good map knows: the free cells of `w` and the blocked cells next to them.
std::vector<KnownCell> mapOf(const sim::World& w) {
  std::vector<KnownCell> known;
  for (int r = 0; r < w.height(); ++r) {
    for (int c = 0; c < w.width(); ++c) {
      const bool nearFree =
          !w.blocked(c + 1, r) || !w.blocked(c - 1, r) || !w.blocked(c, r + 1) || !w.blocked(c, r - 1);
      if (!w.blocked(c, r))
        known.push_back({c, r, CellState::Free});
      else if (nearFree)
        known.push_back({c, r, CellState::Occupied});
    }
  }
  return known;
}

ScoreInput inputFor(const Room& room, std::vector<KnownCell> known) {
  ScoreInput in;
  in.scene = &room.scene;
  in.truth = &room.truth;
  in.frame = room.place.frame;
  in.startCol = room.place.startCol;
  in.startRow = room.place.startRow;
  in.freeCells = 9;
  in.hitCells = 10;
  in.known = std::move(known);
  in.believedCol = in.startCol;
  in.believedRow = in.startRow;
  in.trueCentreCm = Vec2(25, 25);
  return in;
}

struct MovedMap {
  double rotationDeg, shiftCol, shiftRow;
};

// The map is the truth of the room on a grid moved against the robot's: right, but laid down off.
TEST(MapScoreAligned, AMovedPerfectMapScoresLowAsItLiesAndFullyAligned) {
  for (const double heading : {0.0, 10.0}) {
    for (const MovedMap m : {MovedMap{-10.0, 0.0, 0.0}, MovedMap{10.0, 0.0, 0.0}, MovedMap{4.5, 0.25, -0.5},
                             MovedMap{0.0, 0.75, 0.0}, MovedMap{-13.0, -0.5, 0.25}}) {
      SCOPED_TRACE("robot grid at " + std::to_string(heading) + " deg, map moved " + std::to_string(m.rotationDeg) +
                   " deg, " + std::to_string(m.shiftCol) + ", " + std::to_string(m.shiftRow) + " cells");
      const Room room(heading);
      const sim::GridFrame mapFrame =
          movedFrame(room.place.frame, room.place.startCol, room.place.startRow, m.rotationDeg, m.shiftCol, m.shiftRow);
      const sim::World mapTruth = sim::rasterizeScene(room.scene, mapFrame, room.place.width, room.place.height, "map");
      const MapScore s = scoreMap(inputFor(room, mapOf(mapTruth)));
      EXPECT_GT(s.wrongCells, 10);
      EXPECT_LT(s.detectedPct(), 90.0);
      EXPECT_EQ(s.wrongCells, s.unsafeFree + s.phantomOccupied);
      EXPECT_EQ(s.wrongCellsAligned, 0);
      EXPECT_EQ(s.unsafeFreeAligned, 0);
      EXPECT_EQ(s.phantomOccupiedAligned, 0);
      EXPECT_DOUBLE_EQ(s.detectedPctAligned(), 100.0);
      // Nearby moves can draw the same cells; the one found lies within a step of the true one.
      EXPECT_NEAR(s.alignRotationDeg, m.rotationDeg, 0.5 + 1e-9);
      EXPECT_NEAR(s.alignShiftCol, m.shiftCol, 0.25 + 1e-9);
      EXPECT_NEAR(s.alignShiftRow, m.shiftRow, 0.25 + 1e-9);
    }
  }
}

TEST(MapScoreAligned, AMapOffByAThirdOfACellAlignsNearlyWhole) {
  const Room room(10.0);
  const sim::GridFrame mapFrame =
      movedFrame(room.place.frame, room.place.startCol, room.place.startRow, -10.0, 1.0 / 3.0, -1.0 / 3.0);
  const sim::World mapTruth = sim::rasterizeScene(room.scene, mapFrame, room.place.width, room.place.height, "map");
  const MapScore s = scoreMap(inputFor(room, mapOf(mapTruth)));
  EXPECT_GT(s.wrongCells, 20);
  EXPECT_LE(s.wrongCellsAligned * 5, s.wrongCells);
  EXPECT_GT(s.detectedPctAligned(), s.detectedPct() + 20.0);
  EXPECT_NEAR(s.alignRotationDeg, -10.0, 1.0);
}

struct Flip {
  const char* label;
  std::vector<KnownCell> changes;  // replace (or add) these cells of the perfect map
  int unsafeFree, phantomOccupied;
};

TEST(MapScoreSafety, WrongCellsSplitIntoUnsafeFreeAndPhantomOccupied) {
  const Room room;
  const int sc = room.place.startCol, sr = room.place.startRow;
  // (sc - 3, sr) is the wall left of the start (the start is 2.5 cells from the left wall).
  ASSERT_TRUE(room.truth.blocked(sc - 3, sr));
  ASSERT_FALSE(room.truth.blocked(sc - 2, sr));
  const std::vector<Flip> flips = {
      {"perfect map", {}, 0, 0},
      {"a wall cell called free", {{sc - 3, sr, CellState::Free}}, 1, 0},
      {"a free cell called occupied", {{sc + 1, sr, CellState::Occupied}}, 0, 1},
      {"both", {{sc - 3, sr, CellState::Free}, {sc + 1, sr + 1, CellState::Occupied}}, 1, 1},
      {"a cell outside the truth called free", {{-1, 0, CellState::Free}}, 1, 0},
      {"a cell outside the truth called occupied", {{-1, 0, CellState::Occupied}}, 0, 0},
  };
  for (const Flip& f : flips) {
    std::vector<KnownCell> known = mapOf(room.truth);
    for (const KnownCell& change : f.changes) {
      bool replaced = false;
      for (KnownCell& k : known) {
        if (k.col == change.col && k.row == change.row) {
          k.state = change.state;
          replaced = true;
        }
      }
      if (!replaced) known.push_back(change);
    }
    const MapScore s = scoreMap(inputFor(room, known));
    EXPECT_EQ(s.unsafeFree, f.unsafeFree) << f.label;
    EXPECT_EQ(s.phantomOccupied, f.phantomOccupied) << f.label;
    EXPECT_EQ(s.wrongCells, f.unsafeFree + f.phantomOccupied) << f.label;
    // Nothing to gain by moving a map that is right but for a cell or two.
    EXPECT_EQ(s.wrongCellsAligned, s.wrongCells) << f.label;
    EXPECT_EQ(s.unsafeFreeAligned, s.unsafeFree) << f.label;
    EXPECT_DOUBLE_EQ(s.alignRotationDeg, 0.0) << f.label;
  }
}

TEST(MapScoreSafety, LostWhenTheBelievedCellIsNotTheTrueOne) {
  const Room room(10.0);
  struct Case {
    const char* label;
    double alongColCells, alongRowCells;  // true centre moved from the start, cells of the robot's grid
    int believedDc, believedDr;
    bool lost;
  };
  const Case cases[] = {{"at the start, believed there", 0, 0, 0, 0, false},
                        {"0.4 cell off, still in the cell", 0.4, -0.4, 0, 0, false},
                        {"one cell on, believed at the start", 1.0, 0, 0, 0, true},
                        {"one cell on, believed there", 1.0, 0, 1, 0, false},
                        {"0.6 cell back, believed at the start", 0, 0.6, 0, 0, true}};
  for (const Case& c : cases) {
    ScoreInput in = inputFor(room, mapOf(room.truth));
    in.trueCentreCm = room.place.frame.toPlane(Vec2(in.startCol + c.alongColCells, in.startRow + c.alongRowCells));
    in.believedCol = in.startCol + c.believedDc;
    in.believedRow = in.startRow + c.believedDr;
    const MapScore s = scoreMap(in);
    EXPECT_EQ(s.lost, c.lost) << c.label;
    EXPECT_EQ(s.lostAligned, c.lost) << c.label;  // a right map is not moved
  }
}

TEST(MapScoreAligned, NoSceneNoAlignmentAndAnEmptyMapStaysPut) {
  const Room room(10.0);
  ScoreInput in = inputFor(room, {});
  const MapScore empty = scoreMap(in);
  EXPECT_DOUBLE_EQ(empty.alignRotationDeg, 0.0);
  EXPECT_EQ(empty.wrongCellsAligned, 0);
  EXPECT_EQ(empty.unknown, room.place.width * room.place.height);
  in.known = mapOf(sim::rasterizeScene(room.scene, movedFrame(room.place.frame, in.startCol, in.startRow, -10, 0, 0),
                                       room.place.width, room.place.height, "map"));
  in.scene = nullptr;
  const MapScore unmoved = scoreMap(in);
  EXPECT_GT(unmoved.wrongCells, 10);
  EXPECT_EQ(unmoved.wrongCellsAligned, unmoved.wrongCells);
  EXPECT_DOUBLE_EQ(unmoved.detectedPctAligned(), unmoved.detectedPct());
}

}  // namespace
}  // namespace nxtmap::mapping
