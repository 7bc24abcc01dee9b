// The bytes on the wire of every message, for fixed field values. The rows of the messages that
// existed before their fields were written once (Layout) are the bytes the earlier hand-written
// codecs produced for the same values; NewRoom's row is protocol 2's layout, HelloReply's protocol
// 4's (the range geometry after the fresh-session flag).
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "common/protocol/Messages.hpp"

namespace nxtmap::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

struct Row {
  const char* name;
  std::function<size_t(Payload&)> encode;
  std::function<bool(const Bytes&, Payload&)> decodeAndReencode;  // false when refused
  Bytes expected;
};

template <class Msg>
Row row(const char* name, const Msg& m, size_t (*enc)(const Msg&, Payload&), bool (*dec)(const uint8_t*, size_t, Msg&),
        Bytes expected) {
  return Row{name, [m, enc](Payload& p) { return enc(m, p); },
             [enc, dec](const Bytes& b, Payload& p) {
               Msg d;
               if (!dec(b.data(), b.size(), d)) return false;
               return enc(d, p) > 0;
             },
             std::move(expected)};
}

PathMsg fixedPath() {
  PathMsg m;
  m.pathId = 300;
  for (const Cell c : {Cell{5, -2}, Cell{6, -1}, Cell{6, 0}, Cell{5, 0}, Cell{4, -1}}) EXPECT_TRUE(m.append(c));
  return m;
}

MapChunkMsg fixedChunk() {
  MapChunkMsg m;
  m.transferId = 2;
  m.chunkIndex = 1;
  m.chunkCount = 3;
  m.window = Bounds{-5, -6, 10, 9};
  m.offset = 40;
  m.count = 7;
  const CellState s[7] = {CellState::Free, CellState::Occupied, CellState::Unknown, CellState::Occupied,
                          CellState::Free, CellState::Free,     CellState::Occupied};
  for (uint16_t i = 0; i < 7; ++i) m.setState(i, s[i]);
  return m;
}

std::vector<Row> rows() {
  HelloReplyMsg reply;
  reply.version = 1;
  reply.session = 0x01020304u;
  reply.gridHeightLog2 = 5;
  reply.mapEpoch = 0x1234;
  reply.freshSession = true;
  reply.geometry = RangeGeometryMsg{20, 7, 120, 6, 0};  // the brick's (firmware/app/BrickConfig.hpp)
  StatusMsg status;
  status.mode = BrickMode::Following;
  status.pose = Pose{Cell{12, -7}, Dir::South};
  status.batteryMillivolts = 8012;
  status.mapEpoch = 5;
  status.roomId = 3;
  status.path = PathProgressMsg{9, 4, PathState::Following, Cell{11, -7}};
  status.offsetXMm = -2;
  status.offsetYMm = 0x0123;
  const CountersMsg counters{Counters{1, 0x100, 0x10000, 0x1000000, 0xFFFFFFFFu, 99}, LinkCounters{5, 6, 7, 8, 9},
                             -2, 0x1234};
  return {
      row("Hello", HelloMsg{1, 0xA1B2C3D4u, true}, encodeHello, decodeHello, {0x01, 0xD4, 0xC3, 0xB2, 0xA1, 0x01}),
      row("Hello no map", HelloMsg{1, 7u, false}, encodeHello, decodeHello, {0x01, 0x07, 0x00, 0x00, 0x00, 0x00}),
      row("HelloReply", reply, encodeHelloReply, decodeHelloReply,
          {0x01, 0x04, 0x03, 0x02, 0x01, 0x56, 0x34, 0x12, 0x80, 0x00, 0x01, 0x14, 0x07, 0x78, 0x06, 0x00}),
      row("Pose", PoseMsg{Pose{Cell{-3, 300}, Dir::West}}, encodePose, decodePose, {0xFD, 0xFF, 0x2C, 0x01, 0x03}),
      row("PathProgress", PathProgressMsg{0xBEEF, 17, PathState::Blocked, Cell{-200, 45}}, encodePathProgress,
          decodePathProgress, {0xEF, 0xBE, 0x11, 0x00, 0x03, 0x38, 0xFF, 0x2D, 0x00}),
      row("Battery", BatteryMsg{7321}, encodeBattery, decodeBattery, {0x99, 0x1C}),
      row("Status", status, encodeStatus, decodeStatus,
          {0x02, 0x0C, 0x00, 0xF9, 0xFF, 0x02, 0x4C, 0x1F, 0x05, 0x00, 0x03, 0x00, 0x09,
           0x00, 0x04, 0x00, 0x01, 0x0B, 0x00, 0xF9, 0xFF, 0xFE, 0xFF, 0x23, 0x01}),
      row("Counters", counters, encodeCounters, decodeCounters,
          {0x01, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00,
           0x01, 0xFF, 0xFF, 0xFF, 0xFF, 0x05, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00, 0x07, 0x00,
           0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x09, 0x00, 0x00, 0x00, 0xFE, 0xFF, 0x34, 0x12}),
      row("FollowPath", fixedPath(), encodePath, decodePath,
          {0x2C, 0x01, 0x05, 0x00, 0x05, 0x00, 0xFE, 0xFF, 0x01, 0x56}),
      row("MapChunk", fixedChunk(), encodeMapChunk, decodeMapChunk,
          {0x02, 0x00, 0x01, 0x00, 0x03, 0x00, 0xFB, 0xFF, 0xFA, 0xFF,
           0x0A, 0x00, 0x09, 0x00, 0x28, 0x00, 0x07, 0x00, 0x89, 0x25}),
      row("NewRoom (protocol 2)", NewRoomMsg{7, Cell{-1, 2}, 3, Cell{-4, 5}, Dir::East}, encodeNewRoom, decodeNewRoom,
          {0x07, 0x00, 0xFF, 0xFF, 0x02, 0x00, 0x03, 0x00, 0xFC, 0xFF, 0x05, 0x00, 0x01}),
  };
}

TEST(MessageBytes, EveryMessageEncodesToItsFixedBytes) {
  for (const Row& r : rows()) {
    Payload p;
    ASSERT_EQ(r.encode(p), r.expected.size()) << r.name;
    EXPECT_EQ(Bytes(p.bytes, p.bytes + p.size), r.expected) << r.name;
  }
}

TEST(MessageBytes, TheFixedBytesDecodeAndEncodeBackUnchanged) {
  for (const Row& r : rows()) {
    Payload p;
    ASSERT_TRUE(r.decodeAndReencode(r.expected, p)) << r.name;
    EXPECT_EQ(Bytes(p.bytes, p.bytes + p.size), r.expected) << r.name;
    // One byte short and one byte too many: refused.
    EXPECT_FALSE(r.decodeAndReencode(Bytes(r.expected.begin(), r.expected.end() - 1), p)) << r.name;
    Bytes longer = r.expected;
    longer.push_back(0);
    EXPECT_FALSE(r.decodeAndReencode(longer, p)) << r.name;
  }
}

TEST(MessageBytes, DeltaHeaderAndRunsKeepTheirBytes) {
  const CellState s[6] = {CellState::Free,     CellState::Occupied, CellState::Unknown,
                          CellState::Occupied, CellState::Free,     CellState::Free};
  MapDeltaHeader h;
  h.epoch = 0x0203;
  h.heightLog2 = 5;
  h.window = Bounds{-4, -2, 30, 20};
  h.runCount = 9;  // the writer counts runs itself
  Payload p;
  MapDeltaWriter w(p, h);
  EXPECT_EQ(Bytes(p.bytes, p.bytes + p.size),
            (Bytes{0x03, 0x02, 0x56, 0xFC, 0xFF, 0xFE, 0xFF, 0x1E, 0x00, 0x14, 0x00, 0x00}));
  ASSERT_TRUE(w.addRun(66, 6, [&](uint8_t k) { return s[k]; }));  // cells (2..7, 1) of the window
  const uint8_t packed[2] = {0x19, 0x02};
  ASSERT_TRUE(w.addPackedRun(0x0401, 5, packed));  // cells (1..5, 16)
  EXPECT_EQ(Bytes(p.bytes, p.bytes + p.size),
            (Bytes{0x03, 0x02, 0x56, 0xFC, 0xFF, 0xFE, 0xFF, 0x1E, 0x00, 0x14, 0x00,
                   0x02, 0x42, 0x00, 0x06, 0x89, 0x05, 0x01, 0x04, 0x05, 0x19, 0x02}));
  MapDeltaReader r(p.bytes, p.size);
  EXPECT_TRUE(r.validate());
  EXPECT_EQ(r.header().runCount, 2);
}

}  // namespace
}  // namespace nxtmap::protocol
