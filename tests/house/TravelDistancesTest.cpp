// Distances from where the robot stands over the house's known free cells, from small maps drawn as
// text ('#' wall, '.' free, ' ' unknown, 'R' the robot's cell as the map holds it: R free, W wall).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "DrawnMap.hpp"
#include "host/house/TravelDistances.hpp"

namespace nxtmap::house {
namespace {

test::DrawnRoom draw(const std::vector<std::string>& rows) { return test::drawRoom(rows, "#W", ".R", "RW"); }

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
    const test::DrawnRoom d = draw(c.rows);
    const std::vector<int> dist = travelDistances(d.map, d.mark);
    const size_t i = static_cast<size_t>((c.target.y - d.map.minY()) * d.map.width() + (c.target.x - d.map.minX()));
    EXPECT_EQ(dist[i], c.expected) << c.what;
  }
}

TEST(TravelDistances, NothingIsReachedFromOutsideTheMap) {
  const test::DrawnRoom d = draw({"###", "#.#", "###"});
  for (const int v : travelDistances(d.map, Cell{7, 7})) EXPECT_EQ(v, -1);
}

}  // namespace
}  // namespace nxtmap::house
