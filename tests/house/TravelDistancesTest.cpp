// Distances from where the robot stands over the house's known free cells, from small maps drawn as
// text ('#' wall, '.' free, ' ' unknown, 'R' the robot's cell as the map holds it: R free, W wall).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/house/TravelDistances.hpp"

namespace nxtmap::house {
namespace {

struct Drawn {
  network::RoomMap map;
  Cell robot{};
};

// Rows top (highest y) first; the lower-left character is cell (0, 0).
Drawn draw(const std::vector<std::string>& rows) {
  const int h = static_cast<int>(rows.size()), w = static_cast<int>(rows[0].size());
  Drawn d{network::RoomMap(0, 0, w, h), Cell{}};
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const char ch = rows[static_cast<size_t>(r)][static_cast<size_t>(c)];
      const Cell cell{static_cast<int16_t>(c), static_cast<int16_t>(h - 1 - r)};
      if (ch == '#' || ch == 'W') d.map.set(cell, CellState::Occupied);
      if (ch == '.' || ch == 'R') d.map.set(cell, CellState::Free);
      if (ch == 'R' || ch == 'W') d.robot = cell;
    }
  }
  return d;
}

struct Case {
  const char* what;
  std::vector<std::string> rows;
  Cell target;
  int expected;  // -1: not reached
};

TEST(TravelDistances, FromTheRobotOverFreeCells) {
  const std::vector<Case> cases = {
      {"straight along a corridor", {"#####", "#R..#", "#####"}, Cell{3, 1}, 2},
      {"around a wall", {"#####", "#R#.#", "#...#", "#####"}, Cell{3, 2}, 4},
      {"walls and unknown cells are not crossed", {"######", "#R# .#", "######"}, Cell{4, 1}, -1},
      {"the robot's own cell held as a wall by an overlapping room", {"#####", "#W..#", "#####"}, Cell{3, 1}, 2},
      {"a wall cell beside the robot is still a wall", {"#####", "#W#.#", "#####"}, Cell{3, 1}, -1},
  };
  for (const Case& c : cases) {
    const Drawn d = draw(c.rows);
    const std::vector<int> dist = travelDistances(d.map, d.robot);
    const size_t i = static_cast<size_t>((c.target.y - d.map.minY()) * d.map.width() + (c.target.x - d.map.minX()));
    EXPECT_EQ(dist[i], c.expected) << c.what;
  }
}

TEST(TravelDistances, NothingIsReachedFromOutsideTheMap) {
  const Drawn d = draw({"###", "#.#", "###"});
  for (const int v : travelDistances(d.map, Cell{7, 7})) EXPECT_EQ(v, -1);
}

}  // namespace
}  // namespace nxtmap::house
