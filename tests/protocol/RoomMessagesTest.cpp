// The house messages of rooms (EnterRoom, RoomExits, NewRoom): their bytes, their round trips, and every
// malformed payload refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/protocol/Messages.hpp"
#include "tests/protocol/PayloadRefusals.hpp"

namespace nxtmap::protocol {
namespace {

using test::Bytes;
using test::bytesOf;
using test::expectExactLength;
using test::expectRefused;

EnterRoomMsg fixedEnter() {
  EnterRoomMsg m;
  m.roomId = 5;
  m.strategy = ExploreStrategy::Frontier;
  m.door = DoorwayMsg{Cell{3, 9}, 4, 2, true};
  m.outward = Dir::North;
  m.inside = Cell{4, 8};
  return m;
}

TEST(HouseMessages, EnterRoomCarriesTheDoorwayItsSideAndTheNewRoom) {
  Payload p;
  ASSERT_EQ(encodeEnterRoom(fixedEnter(), p), 15u);
  EXPECT_EQ(bytesOf(p),
            (Bytes{0x05, 0x00, 0x01, 0x03, 0x00, 0x09, 0x00, 0x04, 0x02, 0x01, 0x00, 0x04, 0x00, 0x08, 0x00}));
  EnterRoomMsg d;
  ASSERT_TRUE(decodeEnterRoom(p.bytes, p.size, d));
  EXPECT_EQ(d.roomId, 5);
  EXPECT_EQ(d.door.first, (Cell{3, 9}));
  EXPECT_EQ(d.door.width, 4);
  EXPECT_EQ(d.door.depth, 2);
  EXPECT_TRUE(d.door.alongX);
  EXPECT_EQ(d.outward, Dir::North);
  EXPECT_EQ(d.inside, (Cell{4, 8}));
  expectExactLength(bytesOf(p), decodeEnterRoom);
  expectRefused(bytesOf(p),
                {{"strategy 2", 2, 2},
                 {"doorway width 0", 7, 0},
                 {"doorway width 33", 7, 33},
                 {"doorway depth 0", 8, 0},
                 {"doorway depth 9", 8, 9},
                 {"alongX 2", 9, 2},
                 {"outward 4", 10, 4},
                 {"doorway first x 16387", 4, 0x40}},
                decodeEnterRoom);
  expectRefused<EnterRoomMsg>(fixedEnter(),
                              {{"outward along the doorway", [](EnterRoomMsg& m) { m.outward = Dir::East; }},
                               {"outward away from the doorway", [](EnterRoomMsg& m) { m.outward = Dir::South; }},
                               {"inside not next to the doorway",
                                [](EnterRoomMsg& m) {
                                  m.inside = Cell{4, 7};
                                }},
                               {"inside beside the doorway's end",
                                [](EnterRoomMsg& m) {
                                  m.inside = Cell{7, 8};
                                }},
                               {"inside out of range",
                                [](EnterRoomMsg& m) {
                                  m.inside = Cell{4, -16384};
                                }},
                               {"doorway's far corner out of range",
                                [](EnterRoomMsg& m) {
                                  m.door.first = Cell{16380, 9};
                                  m.door.width = 8;
                                  m.inside = Cell{16381, 8};
                                }}},
                              encodeEnterRoom, decodeEnterRoom);
  // The same doorway crossed from its other side, and one along y: good.
  EnterRoomMsg back = fixedEnter();
  back.outward = Dir::South;
  back.inside = Cell{6, 11};
  ASSERT_GT(encodeEnterRoom(back, p), 0u);
  EXPECT_TRUE(decodeEnterRoom(p.bytes, p.size, d));
  EnterRoomMsg alongY = fixedEnter();
  alongY.door = DoorwayMsg{Cell{-6, -1}, 2, 1, false};
  alongY.outward = Dir::West;
  alongY.inside = Cell{-5, 0};
  ASSERT_GT(encodeEnterRoom(alongY, p), 0u);
  EXPECT_TRUE(decodeEnterRoom(p.bytes, p.size, d));
}

RoomExitsMsg fixedExits() {
  RoomExitsMsg m;
  m.roomId = 2;
  m.end = ExplorerEnd::Complete;
  m.count = 2;
  m.exits[0] = RoomExitMsg{DoorwayMsg{Cell{0, 5}, 3, 1, true}, Cell{1, 4}, Dir::North};
  m.exits[1] = RoomExitMsg{DoorwayMsg{Cell{-6, -1}, 2, 2, false}, Cell{-4, 0}, Dir::West};
  return m;
}

TEST(HouseMessages, RoomExitsListsUpToEightExits) {
  Payload p;
  ASSERT_EQ(encodeRoomExits(fixedExits(), p), 4u + 2 * 12u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x02, 0x00, 0x01, 0x02,                    // room, end, count
                               0x00, 0x00, 0x05, 0x00, 0x03, 0x01, 0x01,  // doorway 0
                               0x01, 0x00, 0x04, 0x00, 0x00,              // inside, outward
                               0xFA, 0xFF, 0xFF, 0xFF, 0x02, 0x02, 0x00,  // doorway 1
                               0xFC, 0xFF, 0x00, 0x00, 0x03}));           // inside, outward
  RoomExitsMsg d;
  ASSERT_TRUE(decodeRoomExits(p.bytes, p.size, d));
  EXPECT_EQ(d.end, ExplorerEnd::Complete);
  ASSERT_EQ(d.count, 2);
  EXPECT_EQ(d.exits[1].door.first, (Cell{-6, -1}));
  EXPECT_FALSE(d.exits[1].door.alongX);
  EXPECT_EQ(d.exits[1].inside, (Cell{-4, 0}));
  EXPECT_EQ(d.exits[1].outward, Dir::West);
  expectExactLength(bytesOf(p), decodeRoomExits);
  expectRefused(bytesOf(p),
                {{"end 4", 2, 4},
                 {"count 9", 3, 9},
                 {"count 1 with two exits", 3, 1},
                 {"count 3 with two exits", 3, 3},
                 {"exit 1 alongX 2", 22, 2},
                 {"exit 1 outward 4", 27, 4}},
                decodeRoomExits);
  expectRefused<RoomExitsMsg>(
      fixedExits(),
      {{"exit 0 outward along its doorway", [](RoomExitsMsg& m) { m.exits[0].outward = Dir::West; }},
       {"exit 1 inside not next to its doorway",
        [](RoomExitsMsg& m) {
          m.exits[1].inside = Cell{-3, 0};
        }},
       {"exit 1 doorway width 33", [](RoomExitsMsg& m) { m.exits[1].door.width = 33; }}},
      encodeRoomExits, decodeRoomExits);

  RoomExitsMsg none;
  ASSERT_EQ(encodeRoomExits(none, p), 4u);
  EXPECT_TRUE(decodeRoomExits(p.bytes, p.size, d));
  RoomExitsMsg full = fixedExits();
  full.count = kMaxRoomExits;
  for (RoomExitMsg& e : full.exits) e = full.exits[0];
  ASSERT_EQ(encodeRoomExits(full, p), 4u + kMaxRoomExits * 12u);
  EXPECT_LE(p.size, kMaxPayload);
  EXPECT_TRUE(decodeRoomExits(p.bytes, p.size, d));
  full.count = kMaxRoomExits + 1;
  EXPECT_EQ(encodeRoomExits(full, p), 0u);  // more exits than the message holds
}

TEST(HouseMessages, NewRoomGivesTheNewFrameInTheRoomLeft) {
  Payload p;
  const NewRoomMsg m{7, Cell{-1, 2}, 3, Cell{-4, 5}, Dir::East};
  ASSERT_EQ(encodeNewRoom(m, p), 13u);
  NewRoomMsg d;
  ASSERT_TRUE(decodeNewRoom(p.bytes, p.size, d));
  EXPECT_EQ(d.roomId, 7);
  EXPECT_EQ(d.entry, (Cell{-1, 2}));
  EXPECT_EQ(d.fromRoom, 3);
  EXPECT_EQ(d.origin, (Cell{-4, 5}));
  EXPECT_EQ(d.heading, Dir::East);
  expectExactLength(bytesOf(p), decodeNewRoom);  // protocol 1's 6 bytes among the truncations
  expectRefused(bytesOf(p), {{"entry y 16386", 5, 0x40}, {"origin x 16636", 9, 0x40}, {"heading 4", 12, 4}},
                decodeNewRoom);
}

}  // namespace
}  // namespace nxtmap::protocol
