#include <gtest/gtest.h>

#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/house/RouteDriver.hpp"
#include "host/network/HouseRoute.hpp"

namespace nxtmap::house {
namespace {

const std::string kRoot = std::string(NXTMAP_SOURCE_DIR) + "/worlds/";

// A free cell of the room well inside it: the free cell with the most free cells around it,
// farthest from the entrance among those.
Cell innerCell(const network::RoomMap& m) {
  Cell best{};
  int bestScore = -1;
  for (int y = m.minY(); y <= m.maxY(); ++y) {
    for (int x = m.minX(); x <= m.maxX(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      if (!m.isFree(c)) continue;
      int around = 0;
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) around += m.isFree(offset(c, dx, dy)) ? 1 : 0;
      }
      const int score = around * 1000 + std::abs(x) + std::abs(y);
      if (score > bestScore) {
        bestScore = score;
        best = c;
      }
    }
  }
  return best;
}

// Maps the house, then plans and drives a route between every ordered pair of rooms.
void routesBetweenAllRooms(const sim::World& world, const HouseConfig& config, int expectRooms) {
  HouseMapper m(world, config);
  ASSERT_EQ(m.run(), expectRooms);
  const network::HouseNetwork& h = m.network();
  for (int a = 0; a < expectRooms; ++a) {
    for (int b = 0; b < expectRooms; ++b) {
      if (a == b) continue;
      const network::RoomPoint from{a, innerCell(h.rooms()[static_cast<size_t>(a)].map)};
      const network::RoomPoint to{b, innerCell(h.rooms()[static_cast<size_t>(b)].map)};
      const network::HouseRoute r = network::planHouseRoute(h, from, to);
      ASSERT_TRUE(r.found) << a << "->" << b << ": " << r.error;
      EXPECT_EQ(r.rooms.front(), a);
      EXPECT_EQ(r.rooms.back(), b);
      const std::vector<Cell> cells = r.houseCells(h);
      int col, row;
      m.houseFrame().toWorld(cells.front(), col, row);
      sim::SimRobot robot(world, col, row, config.heading, sim::NoiseProfile{}, 1);
      const DriveResult d = driveRoute(robot, Pose{cells.front(), Dir::North}, cells);
      ASSERT_TRUE(d.arrived) << a << "->" << b;
      int goalCol, goalRow;
      m.houseFrame().toWorld(h.rooms()[static_cast<size_t>(b)].toHouse.apply(to.cell), goalCol, goalRow);
      EXPECT_EQ(robot.col(), goalCol) << a << "->" << b;
      EXPECT_EQ(robot.row(), goalRow) << a << "->" << b;
    }
  }
}

TEST(HouseRoute, EveryPairOfRoomsIsJoinedAndDrivenInTheSimulator) {
  const sim::WorldLoad l = sim::World::load(kRoot + "houses/three-rooms.map");
  ASSERT_TRUE(l.world) << l.error;
  HouseConfig config;
  config.startCol = 8;
  config.startRow = 8;
  routesBetweenAllRooms(*l.world, config, 3);
}

TEST(HouseRoute, HouseExpoPlanRoutesAndLabels) {
  const HousePlanLoad l = loadHouseExpo(kRoot + "houseexpo/house_expo_room_0000.json");
  ASSERT_TRUE(l.plan) << l.error;
  HouseConfig config;
  config.grid = *mapping::GridCapacity::ofCells(128);  // 10 cm cells: its 8 m rooms need more than the brick's grid
  ASSERT_TRUE(defaultStart(*l.plan, config.startCol, config.startRow));
  routesBetweenAllRooms(l.plan->world, config, 4);

  HouseMapper m(l.plan->world, config);
  m.run();
  labelRoomsFromPlan(m, *l.plan);
  network::RoomPoint bedroom;
  ASSERT_TRUE(network::findLabel(m.network(), "bedroom", bedroom));
  const network::HouseRoute r = network::planHouseRoute(m.network(), network::RoomPoint{0, Cell{0, 0}},
                                                        network::RoomPoint{}, plan::Algorithm::AStar, "bedroom");
  ASSERT_TRUE(r.found) << r.error;
  const Cell last = r.legs.back().cells.back();
  EXPECT_LE(std::abs(last.x - bedroom.cell.x), 1);
  EXPECT_LE(std::abs(last.y - bedroom.cell.y), 1);
  EXPECT_FALSE(network::planHouseRoute(m.network(), network::RoomPoint{0, Cell{0, 0}}, network::RoomPoint{},
                                       plan::Algorithm::AStar, "piano")
                   .found);
}

}  // namespace
}  // namespace nxtmap::house
