// Message payloads: every message round-trips, every malformed one is refused.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "common/protocol/Messages.hpp"

namespace nxtmap::protocol {
namespace {

using Bytes = std::vector<uint8_t>;
Bytes bytesOf(const Payload& p) { return Bytes(p.bytes, p.bytes + p.size); }

TEST(Messages, HelloHasAFixedLayoutAndRoundTrips) {
  Payload p;
  ASSERT_EQ(encodeHello(HelloMsg{kProtocolVersion, 0x11223344u, true}, p), 6u);
  EXPECT_EQ(bytesOf(p), (Bytes{kProtocolVersion, 0x44, 0x33, 0x22, 0x11, 0x01}));
  HelloMsg h;
  ASSERT_TRUE(decodeHello(p.bytes, p.size, h));
  EXPECT_EQ(h.session, 0x11223344u);
  EXPECT_TRUE(h.wantMap);
  EXPECT_FALSE(decodeHello(p.bytes, p.size - 1, h));
  p.bytes[5] = 2;
  EXPECT_FALSE(decodeHello(p.bytes, p.size, h));
}

TEST(Messages, StatusAndCountersRoundTripEveryField) {
  StatusMsg s;
  s.mode = BrickMode::Following;
  s.pose = Pose{Cell{-3, 17}, Dir::West};
  s.batteryMillivolts = 7654;
  s.mapEpoch = 9;
  s.roomId = 2;
  s.path = PathProgressMsg{77, 12, PathState::Blocked, Cell{4, -5}};
  s.offsetXMm = -93;
  s.offsetYMm = 1000;
  Payload p;
  ASSERT_EQ(encodeStatus(s, p), 25u);  // small: it must get through a bad link
  StatusMsg d;
  ASSERT_TRUE(decodeStatus(p.bytes, p.size, d));
  EXPECT_EQ(d.mode, s.mode);
  EXPECT_EQ(d.pose.cell, s.pose.cell);
  EXPECT_EQ(d.pose.heading, Dir::West);
  EXPECT_EQ(d.batteryMillivolts, 7654);
  EXPECT_EQ(d.mapEpoch, 9);
  EXPECT_EQ(d.roomId, 2);
  EXPECT_EQ(d.path.state, PathState::Blocked);
  EXPECT_EQ(d.path.at, (Cell{4, -5}));
  EXPECT_EQ(d.offsetXMm, -93);
  EXPECT_EQ(d.offsetYMm, 1000);
  // Truncated at every length, and one byte too many: refused.
  for (size_t n = 0; n < p.size; ++n) EXPECT_FALSE(decodeStatus(p.bytes, n, d)) << n;
  p.bytes[p.size] = 0;
  EXPECT_FALSE(decodeStatus(p.bytes, p.size + 1, d));
  p.bytes[23] = 0xE9;  // offset y 1001 mm: out of range
  EXPECT_FALSE(decodeStatus(p.bytes, p.size, d));
  p.bytes[23] = 0xE8;
  EXPECT_TRUE(decodeStatus(p.bytes, p.size, d));
  p.bytes[0] = 9;  // mode out of range
  EXPECT_FALSE(decodeStatus(p.bytes, p.size, d));

  CountersMsg c{Counters{101, 202, 303, 404, 5}, LinkCounters{1, 2, 3, 4, 0xFFFFFFFFu}, -3491, 2000};
  ASSERT_EQ(encodeCounters(c, p), 44u);
  EXPECT_EQ(p.bytes[4], 202 & 0xFF);
  CountersMsg e;
  ASSERT_TRUE(decodeCounters(p.bytes, p.size, e));
  EXPECT_EQ(e.explorer.rawSamples, 202u);
  EXPECT_EQ(e.explorer.blockedMoves, 5u);
  EXPECT_EQ(e.link.commandsRun, 3u);
  EXPECT_EQ(e.link.retransmits, 0xFFFFFFFFu);
  EXPECT_EQ(e.wheelDrift10UradPerM, -3491);  // -2 deg/m
  EXPECT_EQ(e.wheelTurn10Ppm, 2000);         // +2 %
  EXPECT_FALSE(decodeCounters(p.bytes, p.size - 1, e));
}

TEST(Messages, SmallMessagesRefuseOutOfRangeFields) {
  Payload p;
  PoseMsg pose;
  ASSERT_GT(encodePose(PoseMsg{Pose{Cell{1, 2}, Dir::South}}, p), 0u);
  ASSERT_TRUE(decodePose(p.bytes, p.size, pose));
  EXPECT_EQ(pose.pose.heading, Dir::South);
  p.bytes[4] = 4;
  EXPECT_FALSE(decodePose(p.bytes, p.size, pose));

  PathProgressMsg pp;
  ASSERT_GT(encodePathProgress(PathProgressMsg{3, 2, PathState::Reached, Cell{1, 1}}, p), 0u);
  ASSERT_TRUE(decodePathProgress(p.bytes, p.size, pp));
  EXPECT_EQ(pp.state, PathState::Reached);
  p.bytes[4] = 5;
  EXPECT_FALSE(decodePathProgress(p.bytes, p.size, pp));

  NewRoomMsg room;
  ASSERT_GT(encodeNewRoom(NewRoomMsg{4, Cell{0, -1}}, p), 0u);
  ASSERT_TRUE(decodeNewRoom(p.bytes, p.size, room));
  EXPECT_EQ(room.roomId, 4);
  EXPECT_EQ(room.entry, (Cell{0, -1}));

  BatteryMsg battery;
  ASSERT_EQ(encodeBattery(BatteryMsg{8100}, p), 2u);
  EXPECT_EQ(bytesOf(p), (Bytes{0xA4, 0x1F}));
  ASSERT_TRUE(decodeBattery(p.bytes, p.size, battery));
  EXPECT_EQ(battery.millivolts, 8100);

  HelloReplyMsg reply;
  ASSERT_GT(encodeHelloReply(HelloReplyMsg{}, p), 0u);
  ASSERT_TRUE(decodeHelloReply(p.bytes, p.size, reply));
  EXPECT_EQ(reply.gridWidthLog2, 6);
  p.bytes[5] = 0x08;  // width 2^8: beyond what a delta can name
  EXPECT_FALSE(decodeHelloReply(p.bytes, p.size, reply));
}

TEST(Messages, PathsAreEightNeighbourMovesAndRoundTrip) {
  PathMsg path;
  path.pathId = 42;
  const std::vector<Cell> cells = {{0, 0}, {0, 1}, {1, 2}, {2, 2}, {3, 1}, {3, 0}, {2, -1}, {1, -1}, {0, 0}};
  for (const Cell c : cells) ASSERT_TRUE(path.append(c));
  EXPECT_FALSE(path.append(Cell{2, 0}));  // not a neighbour of (0, 0)
  EXPECT_FALSE(path.append(Cell{0, 0}));  // standing still is not a move
  Payload p;
  ASSERT_EQ(encodePath(path, p), 8u + 4u);
  EXPECT_EQ(bytesOf(p), (Bytes{42, 0, 9, 0, 0, 0, 0, 0, 0x10, 0x32, 0x54, 0x76}));
  PathMsg d;
  ASSERT_TRUE(decodePath(p.bytes, p.size, d));
  ASSERT_EQ(d.count, cells.size());
  for (uint16_t i = 0; i < d.count; ++i) EXPECT_EQ(d.cellAt(i), cells[i]) << i;

  Bytes bad = bytesOf(p);
  bad[8] = 0x18;  // move 8 does not exist
  EXPECT_FALSE(decodePath(bad.data(), bad.size(), d));
  bad = bytesOf(p);
  bad[2] = 0;  // empty path
  EXPECT_FALSE(decodePath(bad.data(), bad.size(), d));
  bad = bytesOf(p);
  bad[2] = 10;  // count disagrees with the moves present
  EXPECT_FALSE(decodePath(bad.data(), bad.size(), d));

  PathMsg full;
  for (int i = 0; i < kMaxPathCells; ++i) ASSERT_TRUE(full.append(Cell{static_cast<int16_t>(i), 0}));
  EXPECT_FALSE(full.append(Cell{kMaxPathCells, 0}));
  ASSERT_GT(encodePath(full, p), 0u);
  ASSERT_TRUE(decodePath(p.bytes, p.size, d));
  EXPECT_EQ(d.cellAt(kMaxPathCells - 1), (Cell{kMaxPathCells - 1, 0}));
}

TEST(Messages, MapChunksCarryRowMajorCellsOfTheWindow) {
  MapChunkMsg m;
  m.transferId = 7;
  m.chunkIndex = 1;
  m.chunkCount = 2;
  m.window = Bounds{-2, -1, 17, 19};  // 20 x 21
  m.offset = 25;
  m.count = 6;
  const CellState states[] = {CellState::Free, CellState::Occupied, CellState::Unknown,
                              CellState::Free, CellState::Free,     CellState::Occupied};
  for (uint16_t i = 0; i < 6; ++i) m.setState(i, states[i]);
  Payload p;
  ASSERT_GT(encodeMapChunk(m, p), 0u);
  MapChunkMsg d;
  ASSERT_TRUE(decodeMapChunk(p.bytes, p.size, d));
  EXPECT_EQ(d.cellOf(0), (Cell{3, 0}));  // offset 25 = row 1, column 5
  EXPECT_EQ(d.cellOf(5), (Cell{8, 0}));
  for (uint16_t i = 0; i < 6; ++i) EXPECT_EQ(d.state(i), states[i]);

  struct Bad {
    const char* what;
    std::function<void(MapChunkMsg&)> spoil;
  };
  const Bad bads[] = {
      {"beyond the window", [](MapChunkMsg& x) { x.offset = 20 * 21 - 3; }},
      {"chunk index past the count", [](MapChunkMsg& x) { x.chunkIndex = 2; }},
      {"empty window", [](MapChunkMsg& x) { x.window = Bounds{}; }},
      {"window wider than 128",
       [](MapChunkMsg& x) {
         x.window = Bounds{0, 0, 128, 3};
       }},
      {"state 3", [](MapChunkMsg& x) { x.states[0] = 0xFF; }},
  };
  for (const Bad& b : bads) {
    MapChunkMsg x = m;
    b.spoil(x);
    Payload q;
    ASSERT_GT(encodeMapChunk(x, q), 0u) << b.what;
    EXPECT_FALSE(decodeMapChunk(q.bytes, q.size, d)) << b.what;
  }
}

TEST(Messages, DeltasNameCellsByTorusIndexAndUnwrapThroughTheWindow) {
  MapDeltaHeader h;
  h.epoch = 3;
  h.window = Bounds{-10, -4, 20, 30};
  Payload p;
  MapDeltaWriter w(p, h);
  // Torus index of (-10, -4) on 64 x 64: x 54, y 60.
  const uint16_t index = static_cast<uint16_t>(60 * 64 + 54);
  const CellState run[] = {CellState::Free, CellState::Occupied, CellState::Free, CellState::Unknown,
                           CellState::Occupied};
  ASSERT_TRUE(w.addRun(index, 5, [&](uint8_t k) { return run[k]; }));
  ASSERT_TRUE(w.addRun(0, 1, [](uint8_t) { return CellState::Free; }));
  EXPECT_EQ(p.size, kDeltaHeaderSize + runBytes(5) + runBytes(1));

  MapDeltaReader r(p.bytes, p.size);
  ASSERT_TRUE(r.validate());
  EXPECT_EQ(r.header().epoch, 3);
  Cell c;
  CellState s;
  std::vector<std::pair<Cell, CellState>> got;
  while (r.next(c, s)) got.emplace_back(c, s);
  ASSERT_EQ(got.size(), 6u);
  EXPECT_EQ(got[0].first, (Cell{-10, -4}));
  EXPECT_EQ(got[4].first, (Cell{-6, -4}));
  EXPECT_EQ(got[4].second, CellState::Occupied);
  EXPECT_EQ(got[5].first, (Cell{0, 0}));

  struct Bad {
    const char* what;
    size_t at;
    uint8_t value;
  };
  const Bad bads[] = {
      {"run crosses its row end", kDeltaHeaderSize + 2, 11},
      {"zero cells", kDeltaHeaderSize + 2, 0},
      {"state 3", kDeltaHeaderSize + 3, 0xC0},
      {"run count too high", kDeltaHeaderSize - 1, 3},
      {"capacity 2^8", 2, 0x68},
      {"window wider than the capacity", 7, 60},                          // maxX = 60: 71 wide
      {"a cell outside the window", kDeltaHeaderSize + runBytes(5), 30},  // torus x 30 is x 30 > maxX 20
  };
  for (const Bad& b : bads) {
    Bytes x(p.bytes, p.bytes + p.size);
    x[b.at] = b.value;
    MapDeltaReader rb(x.data(), x.size());
    EXPECT_FALSE(rb.validate()) << b.what;
    EXPECT_FALSE(rb.next(c, s)) << b.what;
  }
  MapDeltaReader truncated(p.bytes, p.size - 1);
  EXPECT_FALSE(truncated.validate());
}

}  // namespace
}  // namespace nxtmap::protocol
