// RoomConfinement from outside: the robot's path fed to look() over drawn maps, the exits it
// keeps and the cells it holds shut.
#include <gtest/gtest.h>

#include <vector>

#include "common/house/RoomConfinement.hpp"
#include "tests/common/GridFixture.hpp"

namespace nxtmap {
namespace {

constexpr DoorwayLimits kLimits{4, 15, 3, 2};  // the house runs' doorways: 0.4-1.5 m, walls of 2+ cells

struct Confined {
  test::GridFixture f;
  std::vector<uint8_t> reach = std::vector<uint8_t>(packedBytes(32, 32, 1));
  RoomConfinement c{reach.data(), 32, 32, kLimits, 10};

  // Draws the map with the picture cell (ox, rows-1-oy) as the room's start (0,0), then walks
  // the robot along `path` (room frame), looking after every cell.
  Confined(const std::vector<std::string>& rows, int ox, int oy, const std::vector<Cell>& path) {
    f.draw(rows, ox, oy);
    c.begin(nullptr);
    for (const Cell& p : path) c.look(f.map, p);
  }
};

std::vector<Cell> north(int16_t x, int16_t fromY, int16_t toY) {
  std::vector<Cell> p;
  for (int16_t y = fromY; y <= toY; ++y) p.push_back(Cell{x, y});
  return p;
}

TEST(RoomConfinement, ADoorwayDrivenIntoStraightIsAnExitHeldShutBeyondTheRobot) {
  // The robot drove north from S into the gap; from inside it its side readings found one cell of
  // each jamb and its front reading the free cell beyond. Only from there is the doorway seen.
  Confined r({"      .       ",   // y = 5: beyond, seen ahead only
              "   #......#   ",   // y = 4: the door line, the robot in the gap at x = 0
              "#............#",   // y = 3
              "#............#",   //
              "#............#",   //
              "#............#",   // y = 0: the start at x = 0 (picture column 6)
              "##############"},  //
             6, 1, north(0, 0, 4));
  ASSERT_EQ(r.c.exitCount(), 1);
  const RoomExit& e = r.c.exit(0);
  EXPECT_EQ(e.door.first, (Cell{-2, 4}));
  EXPECT_EQ(e.door.width, 6);
  EXPECT_TRUE(e.door.alongX);
  EXPECT_EQ(e.outward, Dir::North);
  EXPECT_EQ(e.inside, (Cell{0, 3}));
  // Held shut one line out, where the robot is not: it can back out, never go on.
  EXPECT_FALSE(r.c.contains(Cell{0, 4}));
  EXPECT_TRUE(r.c.contains(Cell{0, 5}));
  EXPECT_TRUE(r.c.drivesIntoShut(Pose{Cell{0, 4}, Dir::North}, DriveAction::drive(100)));
  EXPECT_FALSE(r.c.drivesIntoShut(Pose{Cell{0, 4}, Dir::North}, DriveAction::drive(-100)));
  r.c.hold(r.f.map);
  EXPECT_EQ(r.f.map.at(Cell{0, 5}), CellState::Occupied);
  EXPECT_EQ(r.f.map.at(Cell{0, 4}), CellState::Free);
  // Done: the line opens again and the exit stays (its inside cell is the room's).
  r.c.finish(r.f.map);
  EXPECT_EQ(r.c.exitCount(), 1);
  EXPECT_EQ(r.f.map.at(Cell{0, 5}), CellState::Free);
}

TEST(RoomConfinement, ACorridorsCrossSectionSeenFromInsideIsNoDoorway) {
  // Along a corridor 4 cells wide; the robot's side readings at x = 5 hit both walls, each with a
  // notch before it (so each looks like a wall's end). Nothing is free beside the "jambs" on the
  // side the robot came from but the notch: not a doorway, the corridor stays one room.
  std::vector<Cell> path;
  for (int16_t x = 0; x <= 5; ++x) path.push_back(Cell{x, 0});
  Confined r({"####.#####",   // y = 3
              ".....?????",   //
              ".....?????",   //
              "..........",   // y = 0: the robot's row from its start, seen ahead
              ".....?????",   //
              "####.#####"},  // y = -2
             0, 2, path);
  EXPECT_EQ(r.c.exitCount(), 0);
  EXPECT_EQ(r.c.ignored(), 0);
}

TEST(RoomConfinement, JambsOfOneCellCountOnlyWhereTheRobotStandsInTheGap) {
  // The same doorway, the robot stopped a cell short of it: one cell of each jamb is no wall's end
  // for the look around (walls of 2+ cells), so nothing is closed yet.
  Confined r({"   #......#   ",   // y = 4
              "#............#",   //
              "#............#",   //
              "#............#",   //
              "#............#",   // y = 0
              "##############"},  //
             6, 1, {Cell{0, 0}, Cell{0, 1}, Cell{0, 2}, Cell{0, 3}});
  EXPECT_EQ(r.c.exitCount(), 0);
}

// The first test's room and doorway, with what the sonar saw beyond it drawn `beyondRows` rows deep.
std::vector<std::string> roomWithSeenBeyond(int beyondRows) {
  std::vector<std::string> rows(static_cast<size_t>(beyondRows), "    ......    ");
  const std::vector<std::string> room = {"   #......#   ", "#............#", "#............#",
                                         "#............#", "#............#", "##############"};
  rows.insert(rows.end(), room.begin(), room.end());
  return rows;
}

// The grid (32 x 32 here) is full along y once the rows seen beyond the doorway reach 26: then what lies
// beyond the exit is forgotten and the room's own far side fits again; with room to spare nothing is.
TEST(RoomConfinement, WhatWasSeenBeyondAnExitIsForgottenOnlyWhenTheGridIsFull) {
  const struct {
    int beyondRows;
    bool full;
  } cases[] = {{26, true}, {20, false}};
  for (const auto& k : cases) {
    Confined r(roomWithSeenBeyond(k.beyondRows), 6, 1, north(0, 0, 4));
    const std::string what = std::to_string(k.beyondRows) + " rows beyond";
    ASSERT_EQ(r.c.exitCount(), 1) << what;
    EXPECT_EQ(r.f.grid().at(Cell{0, 6}), k.full ? CellState::Unknown : CellState::Free) << what;
    EXPECT_EQ(r.f.grid().at(Cell{2, 20}), k.full ? CellState::Unknown : CellState::Free) << what;
    EXPECT_EQ(r.f.grid().window().maxY, k.full ? 5 : 4 + k.beyondRows) << what << ": the shut line stays";
    EXPECT_EQ(r.f.grid().window().minY, -1) << what;
    EXPECT_EQ(r.f.grid().fits(Cell{0, -8}), k.full) << what << ": the room's far side fits again";
    // The room itself, its walls, its doorway and the line held shut beyond it are kept.
    EXPECT_EQ(r.f.grid().at(Cell{0, 3}), CellState::Free) << what;
    EXPECT_EQ(r.f.grid().at(Cell{-6, 0}), CellState::Occupied) << what;
    EXPECT_EQ(r.f.grid().at(Cell{0, -1}), CellState::Occupied) << what;
    EXPECT_EQ(r.f.grid().at(Cell{0, 4}), CellState::Free) << what;
    EXPECT_EQ(r.f.grid().at(Cell{0, 5}), CellState::Occupied) << what << ": held shut";
    EXPECT_FALSE(r.f.map.wasRead(Cell{0, 6}, Dir::North)) << what;
  }
}

}  // namespace
}  // namespace nxtmap
