// Openings onto unknown space that no exit covers, from small rooms drawn as text ('#' wall,
// '.' free, ' ' unknown; rows top = highest y first, the lower-left character is cell (0, 0)).
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "DrawnMap.hpp"
#include "common/house/RoomExit.hpp"
#include "host/house/OpeningSearch.hpp"

namespace nxtmap::house {
namespace {

using test::drawMap;

network::HouseNetwork houseOf(const network::RoomMap& room, const network::RoomTransform& toHouse = {}) {
  network::HouseNetwork n;
  n.addRoom(network::RoomNode{"room0", room, toHouse, {}});
  return n;
}

// A room 8 wide whose top wall is missing over 5 cells; nothing is known above it.
const std::vector<std::string> kOpenTop = {
    "#.....###",
    "#.......#",
    "#.......#",
    "#########",
};

TEST(OpeningSearch, AWideRunOfFreeCellsFacingUnknownSpace) {
  const network::HouseNetwork n = houseOf(drawMap(kOpenTop));
  const std::optional<Opening> o = findOpening(n, n.merged(), {});
  ASSERT_TRUE(o.has_value());
  EXPECT_EQ(o->room, 0);
  EXPECT_EQ(o->outward, Dir::North);
  ASSERT_EQ(o->cells.size(), 5u);
  EXPECT_EQ(o->cells.front(), (Cell{1, 4}));  // the first unknown cells beyond, to cross
  EXPECT_EQ(o->cells.back(), (Cell{5, 4}));
  EXPECT_EQ(o->inside, (Cell{3, 3}));  // the room's cell in front of the middle
}

TEST(OpeningSearch, InTheRoomsFrameWhenTheRoomIsTurned) {
  // The same room turned a quarter clockwise in the house: the opening faces house East.
  const network::RoomTransform toHouse = network::RoomTransform::fromParts(10, 20, 1);
  const network::HouseNetwork n = houseOf(drawMap(kOpenTop), toHouse);
  const std::optional<Opening> o = findOpening(n, n.merged(), {});
  ASSERT_TRUE(o.has_value());
  EXPECT_EQ(o->outward, Dir::North);  // in the room's frame
  EXPECT_EQ(toHouse.apply(o->outward), Dir::East);
  EXPECT_EQ(o->inside, (Cell{3, 3}));
}

TEST(OpeningSearch, NotWhereNoRoomIsLeft) {
  struct Case {
    const char* what;
    std::vector<std::string> rows;
  };
  const std::vector<Case> cases = {
      {"a closed room", {"#########", "#.......#", "#.......#", "#########"}},
      {"a gap narrower than a doorway (a sensing hole)", {"#..######", "#.......#", "#.......#", "#########"}},
      {"known cells a few cells beyond (a shallow alcove, not a room)",
       {"#########", "##     ##", "#.......#", "#.......#", "#########"}},
  };
  for (const Case& c : cases) {
    const network::HouseNetwork n = houseOf(drawMap(c.rows));
    EXPECT_FALSE(findOpening(n, n.merged(), {}).has_value()) << c.what;
  }
}

TEST(OpeningSearch, AnOpeningTriedBeforeIsNotOfferedAgain) {
  const network::HouseNetwork n = houseOf(drawMap(kOpenTop));
  EXPECT_FALSE(findOpening(n, n.merged(), {Cell{3, 3}}).has_value());
  EXPECT_FALSE(findOpening(n, n.merged(), {Cell{4, 2}}).has_value());  // within 2 cells
  EXPECT_TRUE(findOpening(n, n.merged(), {Cell{9, 9}}).has_value());
}

TEST(OpeningSearch, AnOpeningWiderThanADoorwayTheBrickTakesIsCrossedAtItsMiddle) {
  // A room 40 cells wide with no top wall: the brick's EnterRoom holds a doorway of at most 32 cells.
  const std::string wall(42, '#'), inside = "#" + std::string(40, '.') + "#";
  const network::HouseNetwork n = houseOf(drawMap({"." + std::string(40, '.') + ".", inside, inside, wall}));
  const std::optional<Opening> o = findOpening(n, n.merged(), {});
  ASSERT_TRUE(o.has_value());
  ASSERT_EQ(o->cells.size(), static_cast<size_t>(protocol::kMaxDoorwayWidth));
  EXPECT_EQ(o->cells.front(), (Cell{5, 4}));  // 42 free cells from x 0: the middle 32
  EXPECT_EQ(o->cells.back(), (Cell{36, 4}));
  EXPECT_EQ(o->inside, (Cell{21, 3}));
  // As the console sends it: one step outward from the inside cell enters the doorway.
  protocol::EnterRoomMsg m;
  m.roomId = 2;
  m.door = protocol::doorwayMessage(doorwayAround(o->cells.data(), static_cast<int>(o->cells.size())));
  m.outward = o->outward;
  m.inside = o->inside;
  protocol::Payload p;
  protocol::EnterRoomMsg back;
  ASSERT_NE(protocol::encodeEnterRoom(m, p), 0u);
  EXPECT_TRUE(protocol::decodeEnterRoom(p.bytes, p.size, back));
}

}  // namespace
}  // namespace nxtmap::house
