// The room cut: what the house keeps of a room run's map. Maps are drawn with DrawnMap ('#' wall,
// '.' free, ' ' unknown, 'S' the start at 0,0 (free), 'D' a doorway cell (free), 'o' a cell the robot
// stood in (free), 'x' a cell the robot believed it stood in that the map holds as a wall).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/house/RoomCut.hpp"
#include "tests/house/DrawnMap.hpp"

namespace nxtmap::house {
namespace {

struct Drawing {
  network::RoomMap map;
  std::vector<Cell> doors, stood;
};

// The drawing placed so that 'S' is cell 0,0.
Drawing draw(const std::vector<std::string>& rows) {
  const Cell s = test::markedCell(rows, "S");
  Drawing d{test::drawMap(rows, -s.x, -s.y, "#x", ".SDo"), {}, {}};
  const int h = static_cast<int>(rows.size());
  for (int r = 0; r < h; ++r) {
    for (size_t c = 0; c < rows[static_cast<size_t>(r)].size(); ++c) {
      const Cell cell{static_cast<int16_t>(static_cast<int>(c) - s.x), static_cast<int16_t>(h - 1 - r - s.y)};
      const char ch = rows[static_cast<size_t>(r)][c];
      if (ch == 'D') d.doors.push_back(cell);
      if (ch == 'o' || ch == 'x') d.stood.push_back(cell);
    }
  }
  return d;
}

// The cut as a drawing of the same size: '#' wall, '.' free, ' ' not kept (or unknown).
std::vector<std::string> picture(const network::RoomMap& m) {
  std::vector<std::string> rows;
  for (int y = m.maxY(); y >= m.minY(); --y) {
    std::string row;
    for (int x = m.minX(); x <= m.maxX(); ++x) {
      const CellState s = m.at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)});
      row += s == CellState::Occupied ? '#' : s == CellState::Free ? '.' : ' ';
    }
    rows.push_back(row);
  }
  return rows;
}

struct CutCase {
  const char* name;
  std::vector<std::string> run;   // the run's map
  std::vector<std::string> kept;  // the room as the house keeps it
  bool withStood;                 // the cells the robot stood in are given to the cut
};

TEST(RoomCut, KeepsTheCellsItsStartAndTheRobotsCellsReachWithoutCrossingADoorway) {
  const std::vector<CutCase> cases = {
      {"what lies beyond the doorway is left to the next room",
       {"#######  ", "#.....#..", "#..S..D..", "#.....#..", "#######  "},
       {"#######  ", "#.....#  ", "#.....D  ", "#.....#  ", "#######  "},
       false},
      {"the doorway itself is kept",
       {"#####", "#.S.#", "##D##", "#...#", "#####"},
       {"#####", "#...#", "##D##", "     ", "     "},
       false},
      {"a start cut off by a wall mapped astray keeps only its strip, without the cells stood in",
       {"#########", "#....#..#", "#.o..#.S#", "#....#..#", "#########"},
       {"     ####", "     #..#", "     #..#", "     #..#", "     ####"},
       false},
      {"with them the room the robot went on to map is kept too",
       {"#########", "#....#..#", "#.o..#.S#", "#....#..#", "#########"},
       {"#########", "#....#..#", "#....#..#", "#....#..#", "#########"},
       true},
      {"a cell the robot believed it stood in that the map holds as a wall is no way in",
       {"#########", "#....#..#", "#....x.S#", "#....#..#", "#########"},
       {"     ####", "     #..#", "     #..#", "     #..#", "     ####"},
       true},
      {"a cell stood in beyond the doorway still counts: the robot mapped from it",
       {"#########", "#.o..D..#", "#....#.S#", "#########"},
       {"#########", "#....D..#", "#....#..#", "#########"},
       true},
  };
  for (const CutCase& c : cases) {
    SCOPED_TRACE(c.name);
    const Drawing d = draw(c.run);
    const std::vector<Cell> none;
    const network::RoomMap cut = cutToRoom(d.map, d.doors, c.withStood ? d.stood : none);
    std::vector<std::string> expected = c.kept;
    for (std::string& row : expected) {
      for (char& ch : row) ch = ch == 'D' ? '.' : ch;
    }
    EXPECT_EQ(picture(cut), expected);
  }
}

TEST(RoomCut, CellsStoodInOutsideTheMapAreIgnored) {
  const Drawing d = draw({"#####", "#.S.#", "#####"});
  const std::vector<Cell> stood = {Cell{40, 40}, Cell{-40, 0}, Cell{0, 0}};
  EXPECT_EQ(picture(cutToRoom(d.map, d.doors, stood)), picture(d.map));
}

}  // namespace
}  // namespace nxtmap::house
