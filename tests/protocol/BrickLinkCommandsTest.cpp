// The brick's end of the link, driven byte by byte as the firmware drives it: what it takes. LEGO's commands
// answered in order between ours and mailbox messages handed on; our commands run once however often they
// arrive, held while the queue is full, and acknowledged but never run when malformed; the house commands.
#include <gtest/gtest.h>

#include <vector>

#include "common/protocol/BrickLink.hpp"
#include "common/protocol/LegoCommands.hpp"
#include "tests/protocol/BrickLinkFixture.hpp"
#include "tests/protocol/ProtocolTestSupport.hpp"

namespace nxtmap::protocol {
namespace {

using test::BrickLinkTest;
using test::Bytes;
using test::Received;

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

}  // namespace
}  // namespace nxtmap::protocol
