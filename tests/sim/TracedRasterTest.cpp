// The grid laid over a scene (placeOnGrid), rasters traced into scenes (traceRaster) coming back cell for cell,
// and a World made from its cells.
#include "host/sim/TruthRaster.hpp"

#include "host/sim/SceneFromRaster.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "tests/sim/RasterRows.hpp"

namespace nxtmap::sim {
namespace {

using test::box;
using test::joined;
using test::rowsOf;

struct PlaceCase {
  const char* label;
  Vec2 start;
  double headingDeg;
  int startCol, startRow, width, height;
};

TEST(TruthRaster, PlaceOnGridCoversTheSceneWithAMargin) {
  Scene scene;
  scene.addRing(box(10, 10, 50, 40));  // the free area of a 6 x 5 raster whose border cells are blocked
  scene.finish();
  const std::vector<PlaceCase> cases = {
      {"at a cell centre, square: the raster's own grid", Vec2(25, 25), 0.0, 2, 2, 6, 5},
      {"another centre", Vec2(45, 15), 0.0, 4, 1, 6, 5},
      {"off centre: the grid moves with the start", Vec2(27, 25), 0.0, 3, 2, 7, 5},
  };
  for (const PlaceCase& c : cases) {
    const Placement p = placeOnGrid(scene, c.start, c.headingDeg, 10.0);
    EXPECT_EQ(p.startCol, c.startCol) << c.label;
    EXPECT_EQ(p.startRow, c.startRow) << c.label;
    EXPECT_EQ(p.width, c.width) << c.label;
    EXPECT_EQ(p.height, c.height) << c.label;
    const Vec2 back = p.frame.toPlane(Vec2(p.startCol, p.startRow));
    EXPECT_NEAR((back - c.start).norm(), 0.0, 1e-9) << c.label;
  }
}

TEST(TruthRaster, PlaceOnGridTurnedKeepsEveryCornerOneCellInside) {
  Scene scene;
  scene.addRing(box(0, 0, 123, 77));
  scene.finish();
  for (const double heading : {-15.0, 7.5, 10.0, 45.0, 90.0, 200.0}) {
    const Placement p = placeOnGrid(scene, Vec2(30, 30), heading, 10.0);
    EXPECT_NEAR((p.frame.toPlane(Vec2(p.startCol, p.startRow)) - Vec2(30, 30)).norm(), 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(p.frame.headingDeg, heading);
    double minC = 1e9, maxC = -1e9, minR = 1e9, maxR = -1e9;
    for (const Vec2& corner : {Vec2(0, 0), Vec2(123, 0), Vec2(0, 77), Vec2(123, 77)}) {
      const Vec2 g = p.frame.toGrid(corner);
      minC = std::min(minC, g.x());
      maxC = std::max(maxC, g.x());
      minR = std::min(minR, g.y());
      maxR = std::max(maxR, g.y());
    }
    // One whole cell of margin, and no more than one cell beyond it.
    EXPECT_GE(minC, 0.5 - 1e-9) << heading;
    EXPECT_LT(minC, 1.5 + 1e-9) << heading;
    EXPECT_GE(minR, 0.5 - 1e-9) << heading;
    EXPECT_LT(minR, 1.5 + 1e-9) << heading;
    EXPECT_LE(maxC, p.width - 1.5 + 1e-9) << heading;
    EXPECT_GT(maxC, p.width - 2.5 - 1e-9) << heading;
    EXPECT_LE(maxR, p.height - 1.5 + 1e-9) << heading;
    EXPECT_GT(maxR, p.height - 2.5 - 1e-9) << heading;
  }
}

// A raster's free/blocked boundary traced by hand into rings comes back cell for cell.
TEST(TruthRaster, HandTracedRasterComesBackExactly) {
  const std::vector<std::string> raster = {"#######", "#...#.#", "#.#...#", "#.....#", "#######"};
  Scene scene;
  // Free region boundary (cells (1..5, 1..3) less (2,2) and (4,1)), as outline + the islands.
  scene.addRing(Ring{{Vec2(10, 10), Vec2(40, 10), Vec2(40, 20), Vec2(50, 20), Vec2(50, 10), Vec2(60, 10), Vec2(60, 40),
                      Vec2(10, 40)}});
  scene.addRing(box(20, 20, 30, 30));
  scene.finish();
  const Placement p = placeOnGrid(scene, Vec2(15, 15), 0.0, 10.0);
  EXPECT_EQ(p.startCol, 1);
  EXPECT_EQ(p.startRow, 1);
  const World w = rasterizeScene(scene, p.frame, p.width, p.height, "traced");
  EXPECT_EQ(joined(rowsOf(w)), joined(raster));
}

TEST(WorldFromCells, KeepsTheCellsAndRejectsAMismatch) {
  const World w = World::fromCells(3, 2, 0.2, "cells", {0, 1, 0, 7, 0, 0});
  EXPECT_EQ(joined(rowsOf(w)), joined({".#.", "#.."}));
  EXPECT_DOUBLE_EQ(w.resolutionM(), 0.2);
  EXPECT_EQ(w.name(), "cells");
  EXPECT_THROW(World::fromCells(3, 3, 0.2, "bad", {0, 1}), std::invalid_argument);
  EXPECT_THROW(World::fromCells(0, 1, 0.2, "bad", {}), std::invalid_argument);
}

// The raster's own grid: cell (0, 0) centred half a cell in from the plane origin (traceRaster's plane).
GridFrame ownGrid(const World& w) {
  GridFrame f;
  f.cellCm = w.resolutionM() * 100.0;
  f.originCm = Vec2(f.cellCm / 2.0, f.cellCm / 2.0);
  return f;
}

void expectSameCells(const World& a, const World& b, const std::string& label) {
  ASSERT_EQ(a.width(), b.width()) << label;
  ASSERT_EQ(a.height(), b.height()) << label;
  int differ = 0;
  for (int r = 0; r < a.height(); ++r) {
    for (int c = 0; c < a.width(); ++c) differ += a.blocked(c, r) != b.blocked(c, r) ? 1 : 0;
  }
  EXPECT_EQ(differ, 0) << label;
}

TEST(TruthRaster, PublishedWorldsTracedComeBackCellForCell) {
  const std::string dir = std::string(NXTMAP_SOURCE_DIR) + "/worlds/seed-appendix-a/";
  for (const char* name : {"occupancy-089", "occupancy-095", "occupancy-101", "occupancy-107", "occupancy-113",
                           "occupancy-120", "occupancy-127", "occupancy-132", "occupancy-139", "start-positions"}) {
    const WorldLoad load = World::load(dir + name + ".map");
    ASSERT_TRUE(load.world) << load.error;
    const World& w = *load.world;
    const Scene scene = traceRaster(w);
    expectSameCells(rasterizeScene(scene, ownGrid(w), w.width(), w.height(), name), w, name);
    // Placed from a free cell's centre, square: the raster's own grid again.
    int col = -1, row = -1;
    for (int r = 0; r < w.height() && col < 0; ++r) {
      for (int c = 0; c < w.width() && col < 0; ++c) {
        if (!w.blocked(c, r)) std::tie(col, row) = std::make_pair(c, r);
      }
    }
    const double cell = w.resolutionM() * 100.0;
    const Placement p = placeOnGrid(scene, Vec2((col + 0.5) * cell, (row + 0.5) * cell), 0.0, cell);
    EXPECT_EQ(p.startCol, col) << name;
    EXPECT_EQ(p.startRow, row) << name;
    expectSameCells(rasterizeScene(scene, p.frame, p.width, p.height, name), w, name);
  }
}

TEST(TruthRaster, TracedRoomsWithFreeBorderCellsComeBackOnTheirOwnGrid) {
  const std::vector<std::vector<std::string>> rooms = {
      {"....", "....", "...."},
      {"#.#.#", ".....", "#.#.#", "..#.."},
      {"#..#", ".##.", ".##.", "#..#"},  // blocked cells meeting at corners
      {".#.", "#.#", ".#."},
  };
  for (const auto& rows : rooms) {
    for (const double res : {0.10, 0.20, 0.05}) {
      const World w = World::fromRows(rows, res);
      expectSameCells(rasterizeScene(traceRaster(w), ownGrid(w), w.width(), w.height(), "rows"), w,
                      joined(rows) + " at " + std::to_string(res));
    }
  }
}

}  // namespace
}  // namespace nxtmap::sim
