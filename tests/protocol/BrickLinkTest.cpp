// The brick's end of the link, driven byte by byte as the firmware drives it: what it sends. The Hello opens a
// session and the whole state follows, the status periods, the map's deltas until acknowledged and under a new
// epoch, the HelloReply's version and range geometry, and a house's readings and room exits.
#include <gtest/gtest.h>

#include <vector>

#include "common/protocol/BrickLink.hpp"
#include "tests/protocol/BrickLinkFixture.hpp"
#include "tests/protocol/ProtocolTestSupport.hpp"

namespace nxtmap::protocol {
namespace {

using test::BrickLinkTest;
using test::Bytes;
using test::Received;

// While the wheels turn the firmware asks for the cheap frames only: the map's changes wait.
TEST_F(BrickLinkTest, NoMapScanSendsStatusAndRepliesButNoDelta) {
  hello(1);
  collect(0);
  ASSERT_TRUE(o.grid.set(Cell{5, 5}, CellState::Occupied));
  feed({2, 0, 0x00, 0x0D});
  Frame f;
  std::vector<uint8_t> types;
  size_t deltas = 0;
  while (link.transmit(600, report, f, BrickLink::Scope::NoMapScan)) {
    types.push_back(f.bytes[2]);
    deltas += f.bytes[2] == kTypeNxtmap && f.bytes[3] == static_cast<uint8_t>(Op::MapDelta) ? 1 : 0;
  }
  ASSERT_FALSE(types.empty());
  EXPECT_EQ(types[0], kTypeReply);
  EXPECT_EQ(deltas, 0u);
  EXPECT_EQ(collect(700).count(Op::MapDelta), 1u);
}

TEST_F(BrickLinkTest, HelloOpensASessionAndTheWholeStateFollows) {
  ASSERT_TRUE(o.grid.set(Cell{0, 0}, CellState::Free));
  ASSERT_TRUE(o.grid.set(Cell{0, 1}, CellState::Occupied));
  report.pose = Pose{Cell{0, 0}, Dir::East};
  hello(0xC0FFEE);
  const Received r = collect(0);
  ASSERT_FALSE(r.headers.empty());
  EXPECT_EQ(r.headers[0].op, Op::HelloReply);
  HelloReplyMsg reply;
  ASSERT_TRUE(decodeHelloReply(r.payloads[0].data(), r.payloads[0].size(), reply));
  EXPECT_EQ(reply.session, 0xC0FFEEu);
  EXPECT_EQ(reply.gridWidthLog2, 6);
  EXPECT_EQ(reply.mapEpoch, link.mapEpoch());
  EXPECT_TRUE(reply.freshSession);
  for (Op op : {Op::Status, Op::Counters, Op::MapDelta}) EXPECT_EQ(r.count(op), 1u);
  EXPECT_EQ(r.count(Op::Pose), 2u);  // at the Hello and again with the first Status
  EXPECT_EQ(r.count(Op::PathProgress), 2u);
  EXPECT_EQ(r.count(Op::NewRoom), 2u);
  EXPECT_TRUE(mirror.equals(o.grid));
  // Quiet until the next status period; then Status with pose and path again, Counters every other time.
  EXPECT_TRUE(collect(100).headers.empty());
  Received period = collect(500);
  EXPECT_EQ(period.count(Op::Status), 1u);
  EXPECT_EQ(period.count(Op::Pose), 1u);
  EXPECT_EQ(period.count(Op::PathProgress), 1u);
  EXPECT_EQ(period.count(Op::NewRoom), 1u);  // the room's frame, repeated like the pose (a lost one matters)
  EXPECT_EQ(period.count(Op::Counters), 0u);
  EXPECT_EQ(collect(1000).count(Op::Counters), 1u);
  // Pose changes are reported at once.
  report.pose.cell = Cell{1, 0};
  EXPECT_EQ(collect(1010).count(Op::Pose), 1u);
}

TEST_F(BrickLinkTest, StatusTellsWhereInItsCellTheRobotIsBelievedHeldToTheMessagesRange) {
  struct Row {
    int32_t x, y;          // the report's offset, mm
    int16_t sentX, sentY;  // what the Status carries
  };
  const Row rows[] = {{0, 0, 0, 0}, {-93, 47, -93, 47}, {1000, -1000, 1000, -1000}, {1250, -40000, 1000, -1000}};
  hello(0xBEE);
  (void)collect(0);
  uint32_t now = 0;
  for (const Row& row : rows) {
    report.offsetXMm = row.x;
    report.offsetYMm = row.y;
    now += 500;
    const Received r = collect(now);
    const Bytes* status = r.last(Op::Status);
    ASSERT_NE(status, nullptr) << row.x;
    StatusMsg s;
    ASSERT_TRUE(decodeStatus(status->data(), status->size(), s)) << row.x;
    EXPECT_EQ(s.offsetXMm, row.sentX);
    EXPECT_EQ(s.offsetYMm, row.sentY);
  }
}

TEST_F(BrickLinkTest, UnacknowledgedDeltasComeAgainAndAcknowledgedOnesDoNot) {
  hello(1);
  collect(0);
  feed(test::pcPacket(Op::Ack, 0, received));
  ASSERT_TRUE(o.grid.set(Cell{3, 3}, CellState::Occupied));
  Received r = collect(1000);
  ASSERT_EQ(r.count(Op::MapDelta), 1u);
  // No ack: after the retransmission timeout the cell goes again (the Ack of the first delta
  // came at once, so the timeout is down at its floor).
  const uint32_t rto = link.mapSync().retransmitTimeoutMs();
  EXPECT_EQ(rto, MapSync::kMinRtoMs);
  r = collect(1000 + rto - 1);
  EXPECT_EQ(r.count(Op::MapDelta), 0u);
  r = collect(1000 + rto);
  EXPECT_EQ(r.count(Op::MapDelta), 1u);
  EXPECT_EQ(link.counters().retransmits, 1u);
  feed(test::pcPacket(Op::Ack, 0, received));
  r = collect(2000);
  EXPECT_EQ(r.count(Op::MapDelta), 0u);
  EXPECT_EQ(link.mapSync().inFlight(), 0);
  EXPECT_TRUE(mirror.equals(o.grid));
}

TEST_F(BrickLinkTest, RequestMapSendsEverythingUnderANewEpoch) {
  for (int x = 0; x < 10; ++x) ASSERT_TRUE(o.grid.set(Cell{static_cast<int16_t>(x), 0}, CellState::Free));
  hello(1);
  collect(0);
  const uint16_t epoch = link.mapEpoch();
  mirror.cells.clear();
  feed(test::pcPacket(Op::RequestMap, 1, received));
  const Received r = collect(10);
  EXPECT_NE(link.mapEpoch(), epoch);
  EXPECT_EQ(mirror.epoch, link.mapEpoch());
  EXPECT_TRUE(mirror.equals(o.grid));
  EXPECT_TRUE(acknowledges(r.headers.back().ack, r.headers.back().ackMask, 1));
}

TEST_F(BrickLinkTest, AHelloOfAnotherVersionGetsOurVersionAndNoSession) {
  Payload p;
  encodeHello(HelloMsg{static_cast<uint8_t>(kProtocolVersion + 1), 5, false}, p);
  feed(test::pcPacket(Op::Hello, 0, received, &p));
  const Received r = collect(0);
  ASSERT_EQ(r.headers.size(), 1u);
  HelloReplyMsg reply;
  ASSERT_TRUE(decodeHelloReply(r.payloads[0].data(), r.payloads[0].size(), reply));
  EXPECT_EQ(reply.version, kProtocolVersion);
  EXPECT_FALSE(link.connected());
}

// The HelloReply a brick configured with `geometry` gives a Hello.
HelloReplyMsg helloReplyOf(const RangeGeometry& geometry) {
  test::OwnedGrid<> o;
  BrickLinkConfig config;
  config.geometry = rangeGeometryMsgOf(geometry);
  BrickLink link{o.grid, o.shadow, config};
  SeqWindow received;
  Payload p;
  encodeHello(HelloMsg{kProtocolVersion, 9, false}, p);
  for (uint8_t b : test::pcPacket(Op::Hello, 0, received, &p)) link.receive(b);
  Frame f;
  EXPECT_TRUE(link.transmit(0, BrickReport{}, f));
  FrameDecoder d;
  for (uint8_t i = 0; i < f.size; ++i) d.push(f.bytes[i]);
  Telegram t;
  PacketView v;
  HelloReplyMsg reply;
  EXPECT_TRUE(d.pop(t) && parsePacket(t, v) && v.header.op == Op::HelloReply);
  EXPECT_TRUE(decodeHelloReply(v.payload, v.payloadSize, reply));
  return reply;
}

TEST(BrickLinkGeometry, TheHelloReplyTellsTheConfiguredRangeGeometry) {
  struct Case {
    const char* what;
    RangeGeometry g;
  };
  RangeGeometry brick;  // firmware/app/BrickConfig.hpp
  brick.cellCm = 20;
  brick.minCm = 7;
  brick.maxCm = 120;
  brick.mountCm = 6;
  RangeGeometry sure;
  sure.sureCm = 28;
  for (const Case& c :
       {Case{"default (published)", RangeGeometry{}}, Case{"the NXT brick", brick}, Case{"a sure-hit limit", sure}}) {
    const RangeGeometry got = rangeGeometryOf(helloReplyOf(c.g).geometry);
    EXPECT_EQ(got.cellCm, c.g.cellCm) << c.what;
    EXPECT_EQ(got.minCm, c.g.minCm) << c.what;
    EXPECT_EQ(got.maxCm, c.g.maxCm) << c.what;
    EXPECT_EQ(got.mountCm, c.g.mountCm) << c.what;
    EXPECT_EQ(got.sureCm, c.g.sureCm) << c.what;
  }
}

// Readings go out with every status period while the brick reports them, as they are; none otherwise.
TEST_F(BrickLinkTest, ReadingsGoOutEveryStatusPeriodWhileMappingAHouse) {
  hello(13);
  EXPECT_EQ(collect(0).count(Op::Readings), 0u) << "not mapping a house";
  static ReadingsMsg m;  // the fixture's report points at it (static: it outlives the fixture)
  m = ReadingsMsg{};
  m.scanId = 2;
  m.scanPose = Pose{Cell{4, -1}, Dir::South};
  m.scan[3] = RangeReading{RangeStatus::Good, 77, 3};
  m.scan[1] = RangeReading{RangeStatus::TooFar, 180, 3};
  report.readings = &m;
  for (uint32_t period = 1; period <= 3; ++period) {
    const Received r = collect(period * 500);
    ASSERT_EQ(r.count(Op::Readings), 1u) << period;
    ReadingsMsg told;
    ASSERT_TRUE(decodeReadings(r.last(Op::Readings)->data(), r.last(Op::Readings)->size(), told));
    EXPECT_EQ(told.scanId, 2);
    EXPECT_EQ(told.scanPose.cell, (Cell{4, -1}));
    EXPECT_EQ(told.scan[3].cm, 77);
    EXPECT_EQ(told.scan[1].status, RangeStatus::TooFar);
    EXPECT_EQ(told.scan[1].cm, 180);
    EXPECT_EQ(collect(period * 500 + 10).count(Op::Readings), 0u) << period << ": once a period";
  }
}

// RoomExits tells the room's end only once the PC holds every cell of the map.
TEST_F(BrickLinkTest, ARoomsEndIsToldOnlyOnceThePcHoldsTheWholeMap) {
  RoomExitsMsg exits;
  exits.roomId = 2;
  exits.end = ExplorerEnd::Complete;
  report.exits = &exits;
  hello(11);
  ASSERT_TRUE(o.grid.set(Cell{0, 0}, CellState::Free));
  Received first = collect(0);  // the map delta goes out, not yet acknowledged
  ASSERT_NE(first.last(Op::RoomExits), nullptr);
  RoomExitsMsg told;
  ASSERT_TRUE(decodeRoomExits(first.last(Op::RoomExits)->data(), first.last(Op::RoomExits)->size(), told));
  EXPECT_EQ(told.end, ExplorerEnd::Running);
  feed(test::pcPacket(Op::Ack, 0, received));  // the PC acknowledges the delta
  const Received later = collect(600);
  ASSERT_NE(later.last(Op::RoomExits), nullptr);
  ASSERT_TRUE(decodeRoomExits(later.last(Op::RoomExits)->data(), later.last(Op::RoomExits)->size(), told));
  EXPECT_EQ(told.end, ExplorerEnd::Complete);
  EXPECT_EQ(told.roomId, 2);
}

}  // namespace
}  // namespace nxtmap::protocol
