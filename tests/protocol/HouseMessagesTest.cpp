// The house messages: their bytes, their round trips, and every malformed payload refused.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "common/protocol/Messages.hpp"

namespace nxtmap::protocol {
namespace {

using Bytes = std::vector<uint8_t>;
Bytes bytesOf(const Payload& p) { return Bytes(p.bytes, p.bytes + p.size); }

// A good payload of a message: truncated at every length, or one byte longer, it is refused.
template <class Msg>
void expectExactLength(const Bytes& good, bool (*dec)(const uint8_t*, size_t, Msg&)) {
  Msg d;
  ASSERT_TRUE(dec(good.data(), good.size(), d));
  for (size_t n = 0; n < good.size(); ++n) EXPECT_FALSE(dec(good.data(), n, d)) << "truncated to " << n;
  Bytes longer = good;
  longer.push_back(0);
  EXPECT_FALSE(dec(longer.data(), longer.size(), d)) << "trailing byte";
}

// A malformed case: byte `at` of the good payload set to `value`.
struct BadByte {
  const char* what;
  size_t at;
  uint8_t value;
};
template <class Msg>
void expectRefused(const Bytes& good, const std::vector<BadByte>& bads, bool (*dec)(const uint8_t*, size_t, Msg&)) {
  for (const BadByte& b : bads) {
    Bytes x = good;
    ASSERT_LT(b.at, x.size()) << b.what;
    x[b.at] = b.value;
    Msg d;
    EXPECT_FALSE(dec(x.data(), x.size(), d)) << b.what;
  }
}

// A malformed message built from fields (encoders write what they are given).
template <class Msg>
struct BadMsg {
  const char* what;
  std::function<void(Msg&)> spoil;
};
template <class Msg>
void expectRefused(const Msg& good, const std::vector<BadMsg<Msg>>& bads, size_t (*enc)(const Msg&, Payload&),
                   bool (*dec)(const uint8_t*, size_t, Msg&)) {
  for (const BadMsg<Msg>& b : bads) {
    Msg x = good;
    b.spoil(x);
    Payload p;
    ASSERT_GT(enc(x, p), 0u) << b.what;
    Msg d;
    EXPECT_FALSE(dec(p.bytes, p.size, d)) << b.what;
  }
}

TEST(HouseMessages, ExploreIsAStrategyAndAConfineFlag) {
  Payload p;
  ASSERT_EQ(encodeExplore(ExploreMsg{ExploreStrategy::Propagation, true}, p), 2u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x00, 0x01}));
  ExploreMsg d;
  ASSERT_TRUE(decodeExplore(p.bytes, p.size, d));
  EXPECT_EQ(d.strategy, ExploreStrategy::Propagation);
  EXPECT_TRUE(d.confine);
  ASSERT_EQ(encodeExplore(ExploreMsg{ExploreStrategy::Frontier, false}, p), 2u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x01, 0x00}));
  expectExactLength(bytesOf(p), decodeExplore);
  expectRefused(bytesOf(p), {{"strategy 2", 0, 2}, {"flag bit 1", 1, 0x02}, {"flag bit 7", 1, 0x81}}, decodeExplore);
}

TEST(HouseMessages, GoToIsAGoalIdAndACell) {
  Payload p;
  ASSERT_EQ(encodeGoTo(GoToMsg{0x1234, Cell{-2, 300}}, p), 6u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x34, 0x12, 0xFE, 0xFF, 0x2C, 0x01}));
  GoToMsg d;
  ASSERT_TRUE(decodeGoTo(p.bytes, p.size, d));
  EXPECT_EQ(d.goalId, 0x1234);
  EXPECT_EQ(d.target, (Cell{-2, 300}));
  expectExactLength(bytesOf(p), decodeGoTo);
  expectRefused(bytesOf(p), {{"x 16638", 3, 0x40}, {"y 16428", 5, 0x40}}, decodeGoTo);
  expectRefused<GoToMsg>(
      GoToMsg{1, Cell{0, 0}},
      {{"x -16384", [](GoToMsg& m) { m.target.x = -16384; }}, {"y 16384", [](GoToMsg& m) { m.target.y = 16384; }}},
      encodeGoTo, decodeGoTo);
}

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

TEST(HouseMessages, ScanIsTheScansIdOneOrMore) {
  Payload p;
  ASSERT_EQ(encodeScan(ScanMsg{0x0102}, p), 2u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x02, 0x01}));
  ScanMsg d;
  ASSERT_TRUE(decodeScan(p.bytes, p.size, d));
  EXPECT_EQ(d.scanId, 0x0102);
  expectExactLength(bytesOf(p), decodeScan);
  const Bytes zero = {0x00, 0x00};
  EXPECT_FALSE(decodeScan(zero.data(), zero.size(), d)) << "scan id 0";
  const Bytes top = {0xFF, 0xFF};
  EXPECT_TRUE(decodeScan(top.data(), top.size(), d));
}

ReadingsMsg fixedReadings() {
  ReadingsMsg m;
  m.scanId = 3;
  m.scanPose = Pose{Cell{-2, 7}, Dir::East};
  m.scan[0] = RangeReading{RangeStatus::Good, 42, 3};
  m.scan[1] = RangeReading{RangeStatus::NoEcho, 0, 3};
  m.scan[2] = RangeReading{RangeStatus::TooFar, 255, 10};
  m.scan[3] = RangeReading{RangeStatus::Inconsistent, 0, 10};
  return m;
}

TEST(HouseMessages, ReadingsCarryTheLastScan) {
  Payload p;
  ASSERT_EQ(encodeReadings(fixedReadings(), p), 15u);
  EXPECT_EQ(bytesOf(p), (Bytes{0x03, 0x00,                                // scan id
                               0xFE, 0xFF, 0x07, 0x00, 0x01,              // its pose
                               42, 0x30, 0, 0x31, 255, 0xA3, 0, 0xA4}));  // Front, Right, Back, Left
  ReadingsMsg d;
  ASSERT_TRUE(decodeReadings(p.bytes, p.size, d));
  EXPECT_EQ(d.scanId, 3);
  EXPECT_EQ(d.scanPose.cell, (Cell{-2, 7}));
  EXPECT_EQ(d.scanPose.heading, Dir::East);
  const ReadingsMsg m = fixedReadings();
  for (int i = 0; i < kSensorCount; ++i) {
    EXPECT_EQ(d.scan[i].status, m.scan[i].status) << i;
    EXPECT_EQ(d.scan[i].cm, m.scan[i].cm) << i;
    EXPECT_EQ(d.scan[i].samples, m.scan[i].samples) << i;
  }
  expectExactLength(bytesOf(p), decodeReadings);
  expectRefused(bytesOf(p),
                {{"scan pose x 16638", 3, 0x40},
                 {"scan pose heading 4", 6, 4},
                 {"front status 5", 8, 0x35},
                 {"front status 15", 8, 0x3F},
                 {"front samples 11", 8, 0xB0},
                 {"left status 7", 14, 0x47}},
                decodeReadings);
  // Readings the bytes cannot hold are not encoded.
  for (const int16_t cm : {-1, 256}) {
    ReadingsMsg bad = fixedReadings();
    bad.scan[2].cm = cm;
    EXPECT_EQ(encodeReadings(bad, p), 0u) << cm;
  }
  ReadingsMsg none;
  ASSERT_EQ(encodeReadings(none, p), 15u);  // no scan yet
  EXPECT_TRUE(decodeReadings(p.bytes, p.size, d));
  EXPECT_EQ(d.scanId, 0);
}

}  // namespace
}  // namespace nxtmap::protocol
