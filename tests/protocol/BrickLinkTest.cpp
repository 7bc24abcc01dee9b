// The brick's end of the link, driven byte by byte as the firmware drives it.
#include <gtest/gtest.h>

#include <vector>

#include "common/protocol/BrickLink.hpp"
#include "common/protocol/LegoCommands.hpp"
#include "tests/protocol/ProtocolTestSupport.hpp"

namespace nxtmap::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

struct Received {
  std::vector<PacketHeader> headers;
  std::vector<Bytes> payloads;
  std::vector<Telegram> lego;
  size_t count(Op op) const {
    size_t n = 0;
    for (const PacketHeader& h : headers) n += h.op == op ? 1 : 0;
    return n;
  }
  const Bytes* last(Op op) const {
    for (size_t i = headers.size(); i-- > 0;) {
      if (headers[i].op == op) return &payloads[i];
    }
    return nullptr;
  }
};

class BrickLinkTest : public ::testing::Test {
 protected:
  void feed(const Bytes& b) {
    for (uint8_t x : b) link.receive(x);
  }
  // Everything the brick wants to send now, decoded.
  Received collect(uint32_t now) {
    Received r;
    Frame f;
    FrameDecoder d;
    while (link.transmit(now, report, f)) {
      for (uint8_t i = 0; i < f.size; ++i) d.push(f.bytes[i]);
      Telegram t;
      while (d.pop(t)) {
        PacketView v;
        if (parsePacket(t, v)) {
          r.headers.push_back(v.header);
          r.payloads.emplace_back(v.payload, v.payload + v.payloadSize);
          if (v.header.op == Op::MapDelta) {
            mirror.apply(v.payload, v.payloadSize);
            received.record(v.header.seq);
          }
        } else {
          r.lego.push_back(t);
        }
      }
    }
    return r;
  }
  void hello(uint32_t session, bool wantMap = false) {
    Payload p;
    encodeHello(HelloMsg{kProtocolVersion, session, wantMap}, p);
    feed(test::pcPacket(Op::Hello, 0, received, &p));
  }
  std::vector<Command> commands() {
    std::vector<Command> out;
    Command c;
    while (link.nextCommand(c)) out.push_back(c);
    return out;
  }

  test::OwnedGrid<> o;
  BrickLink link{o.grid, o.shadow, BrickLinkConfig{}};
  BrickReport report;
  SeqWindow received;  // the PC's record of the brick's reliable seqs
  test::MirrorMap mirror;
};

TEST_F(BrickLinkTest, AnswersLegoCommandsBeforeAnyHelloButNothingElse) {
  Frame f;
  ASSERT_TRUE(encodeGetBatteryLevel(f));
  feed(Bytes(f.bytes, f.bytes + f.size));
  feed(test::pcPacket(Op::Explore, 1, received));
  report.batteryMillivolts = 7200;
  const Received r = collect(0);
  ASSERT_EQ(r.lego.size(), 1u);
  uint8_t status = 0xFF;
  uint16_t mv = 0;
  ASSERT_TRUE(decodeBatteryReply(r.lego[0], status, mv));
  EXPECT_EQ(mv, 7200);
  EXPECT_TRUE(r.headers.empty());
  EXPECT_TRUE(commands().empty());
}

// LEGO commands between two of ours, some unknown, some wanting no reply: ours are all taken (the
// commands run once, in order) and every LEGO request that wants a reply gets one, in order.
TEST_F(BrickLinkTest, LegoCommandsBetweenOursAreAnsweredInOrderAndOursAreUntouched) {
  hello(1);
  collect(0);
  PathMsg m;
  m.pathId = 7;
  m.count = 1;
  Payload path;
  encodePath(m, path);
  const Bytes stream[] = {
      {2, 0, 0x00, 0x0B},                                  // GET_BATTERY_LEVEL
      test::pcPacket(Op::Stop, 1, received),               // ours
      {6, 0, 0x80, 0x03, 0x2C, 0x01, 0x32, 0x00},          // PLAY_TONE(300, 50), no reply
      {5, 0, 0x80, 0x05, 0x00, 0x0B, 0x00},                // SET_INPUT_MODE, no reply, unknown
      {7, 0, 0x00, 0x09, 12, 3, 'h', 'i', 0},              // MESSAGE_WRITE(12, "hi")
      {2, 0, 0x00, 0x11},                                  // GET_CURRENT_PROGRAM_NAME, unknown
      test::pcPacket(Op::FollowPath, 2, received, &path),  // ours
      {5, 0, 0x00, 0x13, 12, 0, 1},                        // MESSAGE_READ(12)
  };
  for (const Bytes& b : stream) feed(b);
  const std::vector<Command> run = commands();
  ASSERT_EQ(run.size(), 2u);
  EXPECT_EQ(run[0].kind, CommandKind::Stop);
  EXPECT_EQ(run[1].kind, CommandKind::FollowPath);
  const Received r = collect(10);
  std::vector<int> replies;  // opcode * 256 + status
  for (const Telegram& t : r.lego) replies.push_back(t.opcode() * 256 + t.bytes[2]);
  EXPECT_EQ(replies, (std::vector<int>{0x0B00, 0x0900, 0x11BE, 0x1300}));
  EXPECT_EQ(r.lego.back().bytes[5], 'h');
  EXPECT_EQ(link.counters().bytesSkipped, 0u);
}

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

TEST_F(BrickLinkTest, ARepeatedCommandRunsOnceAndIsAcknowledgedEachTime) {
  hello(7);
  collect(0);
  const Bytes explore = test::pcPacket(Op::Explore, 1, received);
  feed(explore);
  feed(explore);  // the ack was lost: the PC sends it again
  const Received r = collect(10);
  const std::vector<Command> cmds = commands();
  ASSERT_EQ(cmds.size(), 1u);
  EXPECT_EQ(cmds[0].kind, CommandKind::Explore);
  EXPECT_EQ(link.counters().duplicates, 1u);
  ASSERT_FALSE(r.headers.empty());
  EXPECT_TRUE(acknowledges(r.headers.back().ack, r.headers.back().ackMask, 1));
  // A reconnect of the same session does not run it again either.
  link.linkLost();
  hello(7);
  feed(explore);
  const Received again = collect(20);
  HelloReplyMsg reply;
  ASSERT_EQ(again.headers[0].op, Op::HelloReply);
  ASSERT_TRUE(decodeHelloReply(again.payloads[0].data(), again.payloads[0].size(), reply));
  EXPECT_FALSE(reply.freshSession);
  EXPECT_TRUE(commands().empty());
  // A new PC session starts afresh.
  hello(8);
  feed(explore);
  EXPECT_EQ(commands().size(), 1u);
}

TEST_F(BrickLinkTest, AFullQueueLeavesTheCommandUnacknowledgedUntilThereIsRoom) {
  hello(1);
  collect(0);
  feed(test::pcPacket(Op::Explore, 1, received));
  feed(test::pcPacket(Op::Stop, 2, received));
  Payload p;
  PathMsg path;
  path.pathId = 5;
  ASSERT_TRUE(path.append(Cell{0, 0}) && path.append(Cell{1, 0}) && path.append(Cell{2, 1}));
  encodePath(path, p);
  const Bytes follow = test::pcPacket(Op::FollowPath, 3, received, &p);
  feed(follow);  // queue of 2 is full: dropped, not acknowledged
  Received r = collect(10);
  ASSERT_FALSE(r.headers.empty());
  EXPECT_EQ(r.headers.back().ack, 2);
  EXPECT_EQ(commands().size(), 2u);
  feed(follow);
  r = collect(20);
  EXPECT_EQ(r.headers.back().ack, 3);
  const std::vector<Command> cmds = commands();
  ASSERT_EQ(cmds.size(), 1u);
  EXPECT_EQ(cmds[0].kind, CommandKind::FollowPath);
  EXPECT_EQ(cmds[0].path.pathId, 5);
  EXPECT_EQ(cmds[0].path.cellAt(2), (Cell{2, 1}));
}

TEST_F(BrickLinkTest, AMalformedCommandIsAcknowledgedButNeverRun) {
  hello(1);
  collect(0);
  Payload p;
  p.size = 3;  // a path of nothing
  feed(test::pcPacket(Op::FollowPath, 1, received, &p));
  const Received r = collect(10);
  EXPECT_TRUE(commands().empty());
  ASSERT_FALSE(r.headers.empty());
  EXPECT_EQ(r.headers.back().ack, 1);
}

TEST_F(BrickLinkTest, SetPoseIsACommandRunOnceAndABadPoseIsNeverRun) {
  hello(1);
  collect(0);
  Payload p;
  ASSERT_GT(encodePose(PoseMsg{Pose{Cell{-3, 7}, Dir::West}}, p), 0u);
  const Bytes setPose = test::pcPacket(Op::SetPose, 1, received, &p);
  feed(setPose);
  feed(setPose);  // resent: runs once
  Received r = collect(10);
  std::vector<Command> cmds = commands();
  ASSERT_EQ(cmds.size(), 1u);
  EXPECT_EQ(cmds[0].kind, CommandKind::SetPose);
  EXPECT_EQ(cmds[0].pose.cell, (Cell{-3, 7}));
  EXPECT_EQ(cmds[0].pose.heading, Dir::West);
  EXPECT_EQ(r.headers.back().ack, 1);
  // A heading outside 0..3 and a short payload: acknowledged, never run.
  p.bytes[4] = 4;
  feed(test::pcPacket(Op::SetPose, 2, received, &p));
  p.size = 4;
  feed(test::pcPacket(Op::SetPose, 3, received, &p));
  r = collect(20);
  EXPECT_TRUE(commands().empty());
  EXPECT_EQ(r.headers.back().ack, 3);
}

TEST_F(BrickLinkTest, CalibrateIsACommandRunOnceAndOneWithAPayloadIsNeverRun) {
  hello(1);
  collect(0);
  const Bytes calibrate = test::pcPacket(Op::Calibrate, 1, received);
  feed(calibrate);
  feed(calibrate);  // resent: runs once
  Received r = collect(10);
  std::vector<Command> cmds = commands();
  ASSERT_EQ(cmds.size(), 1u);
  EXPECT_EQ(cmds[0].kind, CommandKind::Calibrate);
  EXPECT_EQ(r.headers.back().ack, 1);
  Payload p;
  p.size = 1;  // Calibrate carries nothing
  feed(test::pcPacket(Op::Calibrate, 2, received, &p));
  r = collect(20);
  EXPECT_TRUE(commands().empty());
  EXPECT_EQ(r.headers.back().ack, 2);
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

TEST_F(BrickLinkTest, MailboxMessagesReachTheFirmware) {
  Frame f;
  ASSERT_TRUE(encodeMessageWrite(1, "stop", f));
  feed(Bytes(f.bytes, f.bytes + f.size));
  const Received r = collect(0);
  ASSERT_EQ(r.lego.size(), 1u);
  uint8_t status = 0xFF;
  ASSERT_TRUE(decodeMessageWriteReply(r.lego[0], status));
  EXPECT_EQ(status, kLegoOk);
  Mailboxes::Message m;
  ASSERT_EQ(link.mailboxes().read(1, true, m), kLegoOk);
  EXPECT_STREQ(reinterpret_cast<const char*>(m.bytes), "stop");
}

}  // namespace
}  // namespace nxtmap::protocol

namespace nxtmap::protocol {
namespace {

// The house commands: each decoded into its command, run once; a malformed one acknowledged and never run.
TEST_F(BrickLinkTest, HouseCommandsAreDecodedIntoTheirCommands) {
  hello(9);
  collect(0);
  Payload explore, go, enter, badEnter;
  encodeExplore(ExploreMsg{ExploreStrategy::Propagation, true}, explore);
  encodeGoTo(GoToMsg{7, Cell{-3, 12}}, go);
  EnterRoomMsg m;
  m.roomId = 4;
  m.door = DoorwayMsg{Cell{-1, 5}, 4, 1, true};
  m.outward = Dir::North;
  m.inside = Cell{0, 4};
  encodeEnterRoom(m, enter);
  badEnter = enter;
  badEnter.bytes[10] = static_cast<uint8_t>(Dir::East);  // outward East does not cross an along-x doorway
  feed(test::pcPacket(Op::Explore, 1, received, &explore));
  feed(test::pcPacket(Op::GoTo, 2, received, &go));
  std::vector<Command> cmds = commands();
  feed(test::pcPacket(Op::EnterRoom, 3, received, &enter));
  feed(test::pcPacket(Op::EnterRoom, 4, received, &badEnter));
  const std::vector<Command> more = commands();
  cmds.insert(cmds.end(), more.begin(), more.end());
  ASSERT_EQ(cmds.size(), 3u);
  EXPECT_EQ(cmds[0].kind, CommandKind::Explore);
  EXPECT_TRUE(cmds[0].explore.confine);
  EXPECT_EQ(cmds[0].explore.strategy, ExploreStrategy::Propagation);
  EXPECT_EQ(cmds[1].kind, CommandKind::GoTo);
  EXPECT_EQ(cmds[1].goTo.goalId, 7);
  EXPECT_EQ(cmds[1].goTo.target, (Cell{-3, 12}));
  EXPECT_EQ(cmds[2].kind, CommandKind::EnterRoom);
  EXPECT_EQ(cmds[2].enterRoom.roomId, 4);
  EXPECT_EQ(cmds[2].enterRoom.inside, (Cell{0, 4}));
  EXPECT_EQ(link.counters().commandsRun, 3u);
}

// Scan: run once however often it arrives (its acknowledgement lost); a scan id 0 acknowledged, never run.
TEST_F(BrickLinkTest, AScanRunsOnceEvenWhenItArrivesTwice) {
  struct Case {
    const char* name;
    uint16_t scanId;
    int copies;
    size_t runs;
  };
  const Case cases[] = {{"once", 5, 1, 1}, {"twice", 6, 2, 1}, {"three times", 0xFFFF, 3, 1}, {"scan id 0", 0, 2, 0}};
  uint16_t seq = 0;
  hello(12);
  collect(0);
  for (const Case& c : cases) {
    Payload p;
    ASSERT_EQ(encodeScan(ScanMsg{c.scanId}, p), 2u) << c.name;
    const Bytes scan = test::pcPacket(Op::Scan, ++seq, received, &p);
    for (int i = 0; i < c.copies; ++i) feed(scan);
    const Received r = collect(seq * 10u);
    const std::vector<Command> cmds = commands();
    ASSERT_EQ(cmds.size(), c.runs) << c.name;
    if (c.runs == 1) {
      EXPECT_EQ(cmds[0].kind, CommandKind::Scan) << c.name;
      EXPECT_EQ(cmds[0].scan.scanId, c.scanId) << c.name;
    }
    ASSERT_FALSE(r.headers.empty()) << c.name;
    EXPECT_TRUE(acknowledges(r.headers.back().ack, r.headers.back().ackMask, seq)) << c.name;
  }
  EXPECT_EQ(link.counters().duplicates, 1u + 2u + 1u);
  EXPECT_EQ(link.counters().commandsRun, 3u);
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
