// GridLocaliser on maps drawn as text, with readings computed here from a true pose by marching the beam's axis
// through the cells (1 mm steps) and applying the sensor's linear error (BeamModel::expectedReadingMm).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/motion/GridLocaliser.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

constexpr int32_t kCellMm = 200;
constexpr int32_t kMountMm = 60;

// A 6 x 4 room: interior cells x 1..6, y 1..4, walls around.
const std::vector<std::string> kRoom = {
    "########",  //
    "#......#",  //
    "#......#",  //
    "#......#",  //
    "#......#",  //
    "########",  //
};

// A corridor 3 cells wide (y 1..3) and 40 long (x 0..39), open at both ends (unknown beyond).
std::vector<std::string> corridor() {
  const std::string wall(40, '#'), floor(40, '.');
  return {wall, floor, floor, floor, wall};
}

struct TruePose {
  Cell cell;
  int32_t xMm = 0, yMm = 0;  // from the cell's centre
};

// The reading sensor s gives from `truth` facing `facing`: the distance from its face to the first occupied cell
// along its axis, as the NXT reads it (whole cm); BeamModel::kNoEcho past 250 cm.
int16_t readingFrom(const RoomGrid& g, const TruePose& truth, Dir facing, Sensor s) {
  const Dir a = sensorDir(facing, s);
  const int32_t x0 = truth.cell.x * kCellMm + truth.xMm + dx(a) * kMountMm;
  const int32_t y0 = truth.cell.y * kCellMm + truth.yMm + dy(a) * kMountMm;
  for (int32_t mm = 0; mm <= 2500; ++mm) {
    const int32_t x = x0 + dx(a) * mm, y = y0 + dy(a) * mm;
    const auto cellOf = [](int32_t v) {
      return static_cast<int16_t>((v + kCellMm / 2 + 100 * kCellMm) / kCellMm - 100);
    };
    if (g.isOccupied(Cell{cellOf(x), cellOf(y)})) {
      return static_cast<int16_t>((BeamModel().expectedReadingMm(static_cast<int16_t>((mm + 5) / 10)) + 5) / 10);
    }
  }
  return BeamModel::kNoEcho;
}

void readAll(GridLocaliser& loc, const RoomGrid& g, Cell believed, const TruePose& truth, Dir facing) {
  for (const Sensor s : {Sensor::Front, Sensor::Right, Sensor::Back, Sensor::Left}) {
    loc.measure(g, believed, facing, s, readingFrom(g, truth, facing, s));
  }
}

TEST(GridLocaliser, ARobotACellOffIsPulledBack) {
  test::GridFixture f;
  f.draw(kRoom);
  const Cell believed{2, 2};
  const TruePose truth{Cell{3, 2}, 0, 0};
  GridLocaliser loc;
  loc.reset(150, 35);
  EXPECT_EQ(loc.peak().xMm, 0);
  EXPECT_FALSE(loc.rebase().needed);
  for (int round = 0; round < 2; ++round) readAll(loc, f.grid(), believed, truth, Dir::North);
  const GridLocaliser::Peak p = loc.peak();
  EXPECT_EQ(p.xMm, 200);
  EXPECT_EQ(p.yMm, 0);
  const GridLocaliser::Rebase r = loc.rebase();
  EXPECT_TRUE(r.needed);
  EXPECT_EQ(r.dxCells, 1);
  EXPECT_EQ(r.dyCells, 0);
  EXPECT_LT(loc.spreadMm(), 50);
  // The explorer follows: the window moves with the believed cell and the peak is at its centre again.
  loc.recentre(Dir::East, 1);
  EXPECT_EQ(loc.peak().xMm, 0);
  EXPECT_FALSE(loc.rebase().needed);
  readAll(loc, f.grid(), Cell{3, 2}, truth, Dir::North);
  EXPECT_EQ(loc.peak().xMm, 0);
  EXPECT_EQ(loc.peak().yMm, 0);
}

TEST(GridLocaliser, SubCellOffsetsAreFound) {
  const struct {
    int32_t xMm, yMm;
    Dir facing;
  } table[] = {{50, 0, Dir::North}, {-100, 50, Dir::East}, {0, -150, Dir::South}, {150, 100, Dir::West}};
  for (const auto& t : table) {
    test::GridFixture f;
    f.draw(kRoom);
    GridLocaliser loc;
    loc.reset(200, 0);
    readAll(loc, f.grid(), Cell{3, 2}, TruePose{Cell{3, 2}, t.xMm, t.yMm}, t.facing);
    EXPECT_EQ(loc.peak().xMm, t.xMm) << t.xMm << "," << t.yMm;
    EXPECT_EQ(loc.peak().yMm, t.yMm) << t.xMm << "," << t.yMm;
  }
}

TEST(GridLocaliser, AnAmbiguousCorridorKeepsItsPeaksAlongIt) {
  test::GridFixture f;
  f.draw(corridor(), 20, 0);  // the believed cell (0, 2) is in the corridor's middle
  const Cell believed{0, 2};
  GridLocaliser loc;
  loc.reset(100000, 0);  // nothing known along either axis
  for (int round = 0; round < 3; ++round) {
    for (const Sensor s : {Sensor::Left, Sensor::Right}) {  // facing East: across the corridor
      loc.measure(f.grid(), believed, Dir::East, s, readingFrom(f.grid(), TruePose{believed, 0, 0}, Dir::East, s));
    }
  }
  // Across: pinned to the corridor's middle; along: every bin as likely as any (peaks in every cell).
  for (int x = -GridLocaliser::kRadius; x <= GridLocaliser::kRadius; ++x) EXPECT_EQ(loc.at(x, 0, 0), 0) << x;
  EXPECT_GT(loc.at(0, 1, 0), 8);   // 5 cm across: more than a nat
  EXPECT_GT(loc.at(0, -4, 0), 8);  // a cell across
  EXPECT_FALSE(loc.rebase().needed);
  EXPECT_GT(loc.spreadMm(), 250);  // uniform over +-500 mm: 303 mm
}

TEST(GridLocaliser, MotionShiftsThePeakByTheDrivenDistance) {
  GridLocaliser loc;
  loc.reset();
  const struct {
    int32_t mm;
    Dir heading;
    int32_t xMm, yMm;
  } table[] = {{100, Dir::East, 100, 0},
               {75, Dir::North, 100, 100},
               {75, Dir::North, 100, 150},
               {-200, Dir::West, 300, 150},
               {250, Dir::South, 300, -100}};
  for (const auto& t : table) {
    loc.drove(t.mm, t.heading);
    EXPECT_EQ(loc.peak().xMm, t.xMm) << t.mm;
    EXPECT_EQ(loc.peak().yMm, t.yMm) << t.mm;
  }
}

TEST(GridLocaliser, HeadingErrorBecomesSidewaysDrift) {
  GridLocaliser loc;
  loc.reset();
  loc.rotated(GridLocaliser::kQuarterMrad + 70, 1);  // a quarter turn 4 deg too far
  EXPECT_EQ(loc.peak().thetaMrad, 70);
  loc.drove(400, Dir::East);  // 28 mm to the right of East (south): about one bin
  EXPECT_EQ(loc.peak().xMm, 400);
  EXPECT_EQ(loc.peak().yMm, -50);
}

TEST(GridLocaliser, RebasesOnlyWhenConfidentlyInAnotherCell) {
  GridLocaliser loc;
  loc.reset();
  loc.drove(100, Dir::East);  // on the face between the cells: neither
  EXPECT_FALSE(loc.rebase().needed);
  loc.drove(50, Dir::East);
  const GridLocaliser::Rebase r = loc.rebase();
  EXPECT_TRUE(r.needed);
  EXPECT_EQ(r.dxCells, 1);
  loc.recentre(Dir::East, 1);
  EXPECT_EQ(loc.peak().xMm, -50);
  EXPECT_FALSE(loc.rebase().needed);
}

TEST(GridLocaliser, AnEchoFromBeyondTheKnownFreeCellsTellsOnlyWhereItCannotComeFrom) {
  // Free around the believed cell (0, 0), unknown beyond: looking north the first unknown cell's near face is 24 cm
  // from the sensor at the cell's centre. An echo at 40 cm may come from anything beyond it: no position that
  // looks into the unknown within 40 cm is less likely than another. From 20 cm further south the unknown cell's
  // face is 44 cm away, so the echo would come from a free cell: those positions cost more.
  test::GridFixture f;
  f.draw({"...", "...", "..."}, 1, 1);
  GridLocaliser loc;
  loc.reset(150, 35);
  std::vector<uint8_t> before;
  for (int y = -10; y <= 10; ++y) before.push_back(loc.at(0, y, 0));
  loc.measure(f.grid(), Cell{0, 0}, Dir::North, Sensor::Front, 40);
  for (int y = -3; y <= 10; ++y) EXPECT_EQ(loc.at(0, y, 0), before[y + 10]) << y;  // face of the unknown <= 39 cm
  for (int y = -7; y <= -4; ++y) EXPECT_GT(loc.at(0, y, 0), before[y + 10] + 16) << y;  // 44..59 cm: 2 nats more
  // Further south the sensor itself stands in the unknown (its face past the free cells' edge): nothing tells.
  for (int y = -10; y <= -8; ++y) EXPECT_EQ(loc.at(0, y, 0), before[y + 10]) << y;
  // No echo at all: the unknown beyond may hold nothing in reach, so no position is less likely than another.
  GridLocaliser blind;
  blind.reset(150, 35);
  std::vector<uint8_t> all;
  for (int y = -10; y <= 10; ++y)
    for (int x = -10; x <= 10; ++x) all.push_back(blind.at(x, y, 0));
  for (const Sensor s : {Sensor::Front, Sensor::Right, Sensor::Back, Sensor::Left})
    blind.measure(f.grid(), Cell{0, 0}, Dir::North, s, BeamModel::kNoEcho);
  size_t i = 0;
  for (int y = -10; y <= 10; ++y)
    for (int x = -10; x <= 10; ++x) EXPECT_EQ(blind.at(x, y, 0), all[i++]) << x << "," << y;
}

TEST(GridLocaliser, ManyContradictoryUpdatesStayNormalised) {
  test::GridFixture f;
  f.draw(kRoom);
  GridLocaliser loc;
  loc.reset(150, 35);
  const int16_t readings[] = {20, 200, BeamModel::kNoEcho, 0, 7, 95, 254};
  for (int k = 0; k < 700; ++k) {
    const Sensor s = static_cast<Sensor>(k % 4);
    loc.measure(f.grid(), Cell{3, 2}, Dir::North, s, readings[k % 7]);
    if (k % 50 == 0) loc.rotated(k % 100 == 0 ? 40 : -40, 0);
    int lowest = 255;
    for (int h = -2; h <= 2; ++h)
      for (int y = -10; y <= 10; ++y)
        for (int x = -10; x <= 10; ++x) lowest = std::min<int>(lowest, loc.at(x, y, h));
    ASSERT_LE(lowest, GridLocaliser::kSlack) << k;
    ASSERT_LE(loc.spreadMm(), 710) << k;
  }
  // Consistent readings afterwards still find the robot.
  loc.reset(150, 35);
  for (int round = 0; round < 2; ++round) readAll(loc, f.grid(), Cell{3, 2}, TruePose{Cell{3, 2}, 50, 0}, Dir::North);
  EXPECT_EQ(loc.peak().xMm, 50);
  EXPECT_EQ(loc.peak().yMm, 0);
}

}  // namespace
}  // namespace nxtmap
