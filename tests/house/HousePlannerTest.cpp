// HousePlanner, as reports in and orders out: an exit a travel could not pass is tried once more after the
// others, from wherever the robot is then, and only a second failure leaves it unreached; a room is cut from its
// run's map by where the robot started and where it stood; an exit into space a mapped room only glimpsed is
// explored, one into a mapped room joins the two.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "DrawnMap.hpp"
#include "host/house/HousePlanner.hpp"

namespace nxtmap::house {
namespace {

using test::drawMap;

// A room 8 x 4 (house frame = the first room's) with a doorway north (x 3..4) and one east (y 2).
const std::vector<std::string> kRoom = {
    "###..#####", "#........#", "#........#", "#.........", "#........#", "##########",
};

RoomExit exitNorth() { return RoomExit{Doorway{true, Cell{3, 5}, 2, 1}, Cell{3, 4}, Dir::North}; }
RoomExit exitEast() { return RoomExit{Doorway{false, Cell{9, 2}, 1, 1}, Cell{8, 2}, Dir::East}; }

// Drives the planner with a brick that maps the room, is blocked on every travel where it stands and whose
// standing scans say nothing; `arriveOnTry` (0: never) lets the travel of that number (1 = the first) arrive,
// and the crossing after it maps a small room beyond. Returns the exits' inside cells (house frame) the travels
// went to, in order.
std::vector<Cell> travelsUntilDone(HousePlanner& p, int arriveOnTry = 0) {
  std::vector<Cell> travels;
  HouseOrder o = p.start();
  EXPECT_EQ(o.kind, HouseOrder::Kind::ExploreFirstRoom);
  HouseReport mapped;
  mapped.kind = HouseReport::Kind::RoomMapped;
  mapped.map = drawMap(kRoom, 0, 0);
  mapped.pose = Pose{Cell{1, 1}, Dir::North};
  mapped.exits = {exitNorth(), exitEast()};
  o = p.on(mapped);
  for (int guard = 0; guard < 40 && o.kind != HouseOrder::Kind::Finished; ++guard) {
    HouseReport r;
    switch (o.kind) {
      case HouseOrder::Kind::Travel:
        travels.push_back(p.brickToHouse().apply(o.target));
        r.kind = static_cast<int>(travels.size()) == arriveOnTry ? HouseReport::Kind::Arrived
                                                                  : HouseReport::Kind::NotArrived;
        if (r.kind == HouseReport::Kind::Arrived) r.pose = Pose{o.target, Dir::North};
        break;
      case HouseOrder::Kind::Scan:
        r.kind = HouseReport::Kind::Scanned;
        for (RangeReading& s : r.scan) s.status = RangeStatus::Inconsistent;  // says nothing
        break;
      case HouseOrder::Kind::Cross:  // a room 3 x 3 beyond, entered at its south side (its own frame)
        r.kind = HouseReport::Kind::RoomMapped;
        r.map = drawMap({"#####", "#...#", "#...#", "#...#", "##.##"}, -2, -1);
        r.pose = Pose{Cell{0, 1}, Dir::North};
        r.crossedAt = Pose{advance(o.at.cell, o.at.heading, 2), o.at.heading};
        break;
      default: ADD_FAILURE() << "unexpected order " << static_cast<int>(o.kind); return travels;
    }
    o = p.on(r);
  }
  EXPECT_EQ(o.kind, HouseOrder::Kind::Finished);
  return travels;
}

HousePlannerConfig config() {
  HousePlannerConfig c;
  c.maxOpenings = 0;  // the doorways lead to unknown space: no openings explored beside the exits
  return c;
}

TEST(HousePlanner, AnExitNotPassedIsTriedOnceMoreAfterTheOthers) {
  RangeGeometry g;
  g.cellCm = 20;
  HousePlanner p(config(), g);
  const std::vector<Cell> travels = travelsUntilDone(p);
  // The nearer exit first (north, from 1,1), then east; then each once more, in the same order of distance.
  ASSERT_EQ(travels.size(), 4u);
  EXPECT_EQ(travels[0], exitNorth().inside);
  EXPECT_EQ(travels[1], exitEast().inside);
  EXPECT_EQ(travels[2], exitNorth().inside);
  EXPECT_EQ(travels[3], exitEast().inside);
  EXPECT_EQ(p.exitsFound(), 2);
  EXPECT_EQ(p.exitsUnreached(), 2);  // counted once each, after the second try
  EXPECT_EQ(p.exitsLeft(), 0);
}

TEST(HousePlanner, AnExitPassedOnItsSecondTryIsNotCountedUnreached) {
  RangeGeometry g;
  g.cellCm = 20;
  HousePlanner p(config(), g);
  // The third travel (north again) arrives and the robot maps the room beyond; east is then tried once more.
  const std::vector<Cell> travels = travelsUntilDone(p, 3);
  // (From the new room a blocked travel's scan may move the belief and try at once again: attempt 1.)
  ASSERT_GE(travels.size(), 4u);
  EXPECT_EQ(travels[2], exitNorth().inside);
  for (size_t i = 3; i < travels.size(); ++i) EXPECT_EQ(travels[i], exitEast().inside);
  EXPECT_EQ(p.network().rooms().size(), 2u);
  EXPECT_EQ(p.exitsUnreached(), 1);  // east only
}

TEST(HousePlanner, TheRoomKeptIsWhereTheRobotStartedAndWhereItStood) {
  RangeGeometry g;
  g.cellCm = 20;
  // The start (0,0) in a strip a wall mapped astray cuts off from the room the robot went on to map.
  const std::vector<std::string> run = {"#########", "#....#..#", "#....#..#", "#....#..#", "#########"};
  for (const bool withStood : {false, true}) {
    HousePlanner p(config(), g);
    (void)p.start();
    HouseReport mapped;
    mapped.kind = HouseReport::Kind::RoomMapped;
    mapped.map = drawMap(run, -7, -2);
    mapped.pose = Pose{Cell{-5, 0}, Dir::North};
    if (withStood) mapped.stood = {Cell{0, 0}, Cell{0, 1}, Cell{-3, 0}, Cell{-5, 0}};
    (void)p.on(mapped);
    ASSERT_EQ(p.network().rooms().size(), 1u);
    const network::RoomMap& room = p.network().rooms()[0].map;
    EXPECT_TRUE(room.isFree(Cell{-1, 0}));
    EXPECT_EQ(room.isFree(Cell{-5, 0}), withStood) << (withStood ? "with" : "without") << " the cells stood in";
  }
}

// The first room (house frame) with a doorway north into a second room, and west of that doorway a wide opening
// the run did not take for a doorway: through it the robot saw 3 rows of the space beyond (x 0..4, y 6..8), up to
// its range; `farSide` is what it saw at x = -1 beyond them (' ' nothing, '#' a wall: the space is closed).
std::vector<std::string> firstRoomWithAGlimpse(char farSide) {
  const std::string glimpse = std::string(1, farSide) + ".....        ";
  return {glimpse,          glimpse,          glimpse,          "#.....##..####", "#............#",
          "#............#", "#............#", "#............#", "#............#", "##############"};
}

// Maps the first room, travels to its north doorway, crosses it and maps the second room (x 5..11, y 5..10 of the
// house), whose west doorway (x 5, y 7..8) opens onto the space glimpsed from the first. The order then.
HouseOrder afterTheSecondRoom(HousePlanner& p, char farSide) {
  HouseOrder o = p.start();
  HouseReport first;
  first.kind = HouseReport::Kind::RoomMapped;
  first.map = drawMap(firstRoomWithAGlimpse(farSide), -1, -1);
  first.pose = Pose{Cell{1, 1}, Dir::North};
  first.exits = {RoomExit{Doorway{true, Cell{7, 5}, 2, 1}, Cell{7, 4}, Dir::North}};
  o = p.on(first);
  EXPECT_EQ(o.kind, HouseOrder::Kind::Travel);
  HouseReport arrived;
  arrived.kind = HouseReport::Kind::Arrived;
  arrived.pose = Pose{o.target, Dir::North};
  o = p.on(arrived);
  EXPECT_EQ(o.kind, HouseOrder::Kind::Cross);
  // The second room in its own frame: the crossing at house 7,6, facing north.
  HouseReport second;
  second.kind = HouseReport::Kind::RoomMapped;
  second.map = drawMap({"#######", "#.....#", "......#", "......#", "#.....#", "##..###"}, -2, -1);
  second.pose = Pose{Cell{0, 1}, Dir::North};
  second.crossedAt = Pose{advance(o.at.cell, o.at.heading, 2), o.at.heading};
  second.exits = {RoomExit{Doorway{false, Cell{-2, 1}, 2, 1}, Cell{-1, 1}, Dir::West}};
  return p.on(second);
}

RangeGeometry brickCells() {
  RangeGeometry g;
  g.cellCm = 20;
  return g;
}

// A new room's frame as the crossing put it (no registration on the rooms mapped).
HousePlannerConfig unregistered() {
  HousePlannerConfig c = config();
  c.registerCells = 0;
  return c;
}

TEST(HousePlanner, AnExitIntoSpaceAMappedRoomOnlyGlimpsedIsExplored) {
  HousePlanner p(unregistered(), brickCells());
  const HouseOrder o = afterTheSecondRoom(p, ' ');
  ASSERT_EQ(o.kind, HouseOrder::Kind::Travel);
  EXPECT_EQ(p.brickToHouse().apply(o.target), (Cell{6, 7}));  // the west doorway's inside cell
  EXPECT_EQ(p.network().gateways().size(), 1u);               // the north doorway only
}

TEST(HousePlanner, AnExitIntoAMappedRoomJoinsTheTwoWithoutARun) {
  HousePlanner p(unregistered(), brickCells());
  const HouseOrder o = afterTheSecondRoom(p, '#');  // the space beyond the opening is the first room's own
  EXPECT_EQ(o.kind, HouseOrder::Kind::Finished);
  ASSERT_EQ(p.network().gateways().size(), 2u);
  EXPECT_EQ(p.network().gateways()[1].roomA, 1);
  EXPECT_EQ(p.network().gateways()[1].roomB, 0);
}

}  // namespace
}  // namespace nxtmap::house
