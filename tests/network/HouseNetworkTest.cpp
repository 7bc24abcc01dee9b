#include <gtest/gtest.h>

#include "host/network/HouseNetwork.hpp"

namespace nxtmap::network {
namespace {

Cell C(int x, int y) { return Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}; }

TEST(RoomTransform, QuarterTurnsAndTranslations) {
  const RoomTransform east = RoomTransform::fromPose(C(10, 5), Dir::East);
  EXPECT_EQ(east.apply(C(0, 0)), C(10, 5));
  EXPECT_EQ(east.apply(C(0, 1)), C(11, 5));  // the room's +y points East
  EXPECT_EQ(east.apply(C(1, 0)), C(10, 4));  // its +x points South
  EXPECT_EQ(east.apply(Dir::North), Dir::East);
  const RoomTransform inv = east.inverse();
  for (int x = -3; x <= 3; ++x) {
    for (int y = -3; y <= 3; ++y) EXPECT_EQ(inv.apply(east.apply(C(x, y))), C(x, y));
  }
  const RoomTransform south = RoomTransform::fromPose(C(-2, 7), Dir::South);
  const RoomTransform both = east * south;
  EXPECT_EQ(both.quarterTurns(), 3);
  EXPECT_EQ(both.apply(C(4, -1)), east.apply(south.apply(C(4, -1))));
  EXPECT_EQ(both.inverse() * both, RoomTransform());
  EXPECT_NEAR(east.isometry().rotation()(0, 1), 1.0, 1e-12);
}

HouseNetwork threeRooms() {
  HouseNetwork n;
  for (int i = 0; i < 3; ++i) {
    RoomNode r;
    r.name = "room" + std::to_string(i);
    r.map = RoomMap(0, 0, 4, 3);
    for (int y = 0; y < 3; ++y) {
      for (int x = 0; x < 4; ++x) r.map.set(C(x, y), CellState::Free);
    }
    r.map.set(C(3, 2), CellState::Occupied);
    r.toHouse = RoomTransform::fromParts(4 * i, 0, 0);
    n.addRoom(std::move(r));
  }
  n.addGateway(Gateway{0, 1, {C(3, 1)}, {C(-1, 1)}});
  n.addGateway(Gateway{1, 2, {C(3, 0)}, {C(-1, 0)}});
  return n;
}

TEST(HouseNetwork, RoutesOverGateways) {
  HouseNetwork n = threeRooms();
  EXPECT_EQ(n.roomRoute(0, 2), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(n.roomRoute(2, 0), (std::vector<int>{2, 1, 0}));
  EXPECT_EQ(n.roomRoute(1, 1), (std::vector<int>{1}));
  EXPECT_TRUE(n.roomRoute(0, 3).empty());
  RoomNode lonely;
  lonely.name = "attic";
  lonely.map = RoomMap(0, 0, 1, 1);
  n.addRoom(lonely);
  EXPECT_TRUE(n.roomRoute(0, 3).empty());
  EXPECT_EQ(n.roomIndex("attic"), 3);
  EXPECT_EQ(n.roomIndex("cellar"), -1);
  EXPECT_EQ(n.gatewaysBetween(2, 1), (std::vector<int>{1}));
}

TEST(HouseNetwork, ValidationNamesTheProblem) {
  std::string e;
  EXPECT_TRUE(threeRooms().validate(e)) << e;
  HouseNetwork dup = threeRooms();
  dup.rooms()[1].name = "room0";
  EXPECT_FALSE(dup.validate(e));
  EXPECT_NE(e.find("two rooms"), std::string::npos);
  HouseNetwork bad = threeRooms();
  bad.addGateway(Gateway{0, 7, {C(0, 0)}, {C(0, 0)}});
  EXPECT_FALSE(bad.validate(e));
  EXPECT_NE(e.find("does not exist"), std::string::npos);
  HouseNetwork self = threeRooms();
  self.addGateway(Gateway{1, 1, {C(0, 0)}, {C(0, 0)}});
  EXPECT_FALSE(self.validate(e));
  HouseNetwork uneven = threeRooms();
  uneven.addGateway(Gateway{0, 1, {C(0, 0)}, {}});
  EXPECT_FALSE(uneven.validate(e));
  HouseNetwork wall = threeRooms();
  wall.addGateway(Gateway{0, 1, {C(3, 2)}, {C(0, 0)}});
  EXPECT_FALSE(wall.validate(e));
  EXPECT_NE(e.find("wall"), std::string::npos);
}

TEST(HouseNetwork, MergedMapVotesAndOccupiedWinsTies) {
  HouseNetwork n;
  RoomNode a, b;
  a.name = "a";
  b.name = "b";
  a.map = RoomMap(0, 0, 2, 1);
  a.map.set(C(0, 0), CellState::Free);
  a.map.set(C(1, 0), CellState::Free);
  b.map = RoomMap(0, 0, 2, 1);  // turned half a turn, at house (1, 0): covers house (1,0) and (0,0)
  b.map.set(C(0, 0), CellState::Occupied);
  b.toHouse = RoomTransform::fromPose(C(1, 0), Dir::South);
  n.addRoom(a);
  n.addRoom(b);
  const RoomMap m = n.merged();
  EXPECT_EQ(m.minX(), 0);
  EXPECT_EQ(m.width(), 2);
  EXPECT_EQ(m.at(C(1, 0)), CellState::Occupied);  // one free vote, one occupied vote
  EXPECT_EQ(m.at(C(0, 0)), CellState::Free);
  EXPECT_EQ(m.at(C(5, 5)), CellState::Unknown);
}

}  // namespace
}  // namespace nxtmap::network
