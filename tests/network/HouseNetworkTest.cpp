#include <gtest/gtest.h>

#include <functional>

#include "host/network/HouseLimits.hpp"
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

// The bounds of HouseLimits hold for a network built in memory too (saveHouse validates it), so a
// house that saves also loads.
TEST(HouseNetwork, ValidationKeepsTheHouseWithinItsLimits) {
  struct Case {
    std::string what;
    std::function<void(HouseNetwork&)> change;
    std::string message;  // "" when the network stays valid
  };
  const std::vector<Case> cases = {
      {"a room's box beyond the coordinate range", [](HouseNetwork& n) { n.rooms()[1].map = RoomMap(8190, 0, 4, 3); },
       "room 'room1': its map (cells 8190..8193 x 0..2) reaches beyond cells -8192..8192"},
      {"to_house beyond the coordinate range",
       [](HouseNetwork& n) { n.rooms()[2].toHouse = RoomTransform::fromParts(2147483647, 0, 0); },
       "room 'room2': to_house x, y (2147483647, 0) must lie within -8192..8192 cells"},
      {"rooms far apart", [](HouseNetwork& n) { n.rooms()[2].toHouse = RoomTransform::fromParts(0, -8000, 1); },
       "the rooms span 8 x 8006 cells in the house frame, more than 2048 a side"},
      {"rooms at the largest extent",
       [](HouseNetwork& n) { n.rooms()[2].toHouse = RoomTransform::fromParts(2044, 0, 0); }, ""},
      {"a label outside its room", [](HouseNetwork& n) { n.rooms()[0].labels["chair"] = C(4, 0); },
       "room 'room0': label 'chair' at [4, 0] lies outside the room's map (cells 0..3 x 0..2)"},
      {"a label on its room's edge", [](HouseNetwork& n) { n.rooms()[0].labels["chair"] = C(3, 2); }, ""},
      {"a gateway cell far outside its room",
       [](HouseNetwork& n) {
         n.addGateway(Gateway{0, 2, {C(30000, 1)}, {C(0, 0)}});
       },
       "gateway 2: cells_a [30000, 1] lies outside room 'room0' (more than 8 cells from its map, cells 0..3 x 0..2)"},
      {"a gateway cell nine cells out",
       [](HouseNetwork& n) {
         n.addGateway(Gateway{0, 2, {C(1, 1)}, {C(-9, 0)}});
       },
       "gateway 2: cells_b [-9, 0] lies outside room 'room2'"},
      {"a gateway cell eight cells out",
       [](HouseNetwork& n) {
         n.addGateway(Gateway{0, 2, {C(1, 1)}, {C(0, -8)}});
       },
       ""},
      {"a room with no map yet holds its entrance",
       [](HouseNetwork& n) {
         RoomNode r;
         r.name = "new";
         r.toHouse = RoomTransform::fromParts(12, 0, 0);
         n.addGateway(Gateway{2, n.addRoom(r), {C(3, 1)}, {C(0, 0)}});
       },
       ""},
      {"too many rooms",
       [](HouseNetwork& n) {
         for (int i = 0; i < kMaxRooms; ++i)
           n.addRoom(RoomNode{"extra" + std::to_string(i), RoomMap(0, 0, 1, 1), {}, {}});
       },
       "259 rooms, more than 256"},
      {"too many cells",
       [](HouseNetwork& n) {
         for (int i = 0; i < 5; ++i) n.addRoom(RoomNode{"big" + std::to_string(i), RoomMap(0, 0, 2048, 2048), {}, {}});
       },
       "the room maps hold more than 16777216 cells together"},
  };
  for (const Case& c : cases) {
    HouseNetwork n = threeRooms();
    c.change(n);
    std::string e;
    EXPECT_EQ(n.validate(e), c.message.empty()) << c.what << ": " << e;
    if (!c.message.empty()) {
      EXPECT_NE(e.find(c.message), std::string::npos) << c.what << ": " << e;
    }
  }
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
