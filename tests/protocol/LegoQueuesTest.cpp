// The LEGO server's queues: requests answered in order and a full queue dropping and counting; the mailboxes as
// LEGO keeps them; the PC side's commands round-tripped through the server.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/protocol/LegoCommands.hpp"
#include "common/protocol/LegoServer.hpp"
#include "tests/protocol/FakeLegoBrick.hpp"

namespace nxtmap::protocol {
namespace {

using test::Bytes;
using test::cat;
using test::FakeBrick;
using test::idle;
using test::telegramOf;

TEST(LegoServer, BackToBackRequestsAreAnsweredInOrder) {
  LegoServer s;
  FakeBrick brick;
  std::vector<Bytes> requests;
  std::vector<uint8_t> expected;  // the opcode of each reply, in order
  for (int i = 0; i < 40; ++i) {
    const uint8_t ops[] = {0x0B, 0x0D, 0x11, 0x0C, 0x01};
    const uint8_t op = ops[i % 5];
    requests.push_back({0x00, op});
    expected.push_back(op);
    if (i % 3 == 0) requests.push_back({0x80, 0x05, 0x00, 0x0B, 0x00});        // no reply, unknown: no trace
    if (i % 4 == 0) requests.push_back({0x80, 0x03, 0x00, 0x01, 0x10, 0x00});  // no reply, served
  }
  std::vector<uint8_t> got;
  Frame f;
  for (const Bytes& r : requests) {
    s.take(telegramOf(r));
    if (!s.hasRoom()) {
      while (s.next(idle(), brick, f)) got.push_back(f.bytes[3]);
    }
  }
  while (s.next(idle(), brick, f)) got.push_back(f.bytes[3]);
  EXPECT_EQ(got, expected);
  EXPECT_EQ(brick.tones.size(), 10u);
  EXPECT_EQ(s.dropped(), 0u);
}

TEST(LegoServer, AFullQueueDropsAndCounts) {
  LegoServer s;
  FakeBrick brick;
  const Bytes write = cat({0x00, 0x09, 0, 59}, cat(Bytes(58, 'a'), {0}));
  size_t taken = 0;
  while (s.hasRoom()) {
    s.take(telegramOf(write));
    ++taken;
  }
  s.take(telegramOf(write));
  s.take(telegramOf(write));
  EXPECT_EQ(taken, LegoServer::kQueueBytes / 64);
  EXPECT_EQ(s.dropped(), 2u);
}

TEST(Mailboxes, KeepFiveAndDropTheOldestAsLegoDoes) {
  Mailboxes m;
  auto text = [](char c) { return Bytes{static_cast<uint8_t>(c), 0}; };
  for (char c = 'a'; c <= 'g'; ++c) ASSERT_EQ(m.write(4, text(c).data(), 2), kLegoOk);
  EXPECT_EQ(m.count(4), kLegoMessagesPerBox);
  Mailboxes::Message out;
  std::string order;
  while (m.read(4, true, out) == kLegoOk) order += static_cast<char>(out.bytes[0]);
  EXPECT_EQ(order, "cdefg");
  EXPECT_EQ(m.used(), 0u);
  // The shared pool: full messages in several queues until it is full.
  const Bytes full = cat(Bytes(58, 'x'), {0});
  uint8_t st = kLegoOk;
  int written = 0;
  for (uint8_t box = 0; box < kLegoMailboxes && st == kLegoOk; ++box) {
    st = m.write(box, full.data(), 59);
    written += st == kLegoOk ? 1 : 0;
  }
  EXPECT_EQ(st, kLegoNoMemory);
  EXPECT_EQ(written, static_cast<int>(Mailboxes::kPoolBytes / 61));
  // Reading without removing leaves it; the other queues are untouched.
  ASSERT_EQ(m.read(1, false, out), kLegoOk);
  EXPECT_EQ(m.count(1), 1);
  EXPECT_EQ(m.read(19, true, out), kLegoMailboxEmpty);
  EXPECT_EQ(m.write(2, text('z').data(), 1), kLegoOutOfRange);  // size 1 must be the NUL alone
}

TEST(LegoCommands, PcSideEncodersAndReplyDecodersRoundTrip) {
  LegoServer s;
  FakeBrick brick;
  Frame req, rep;
  auto ask = [&](const Frame& q) {
    s.take(telegramOf(Bytes(q.bytes + 2, q.bytes + q.size)));
    EXPECT_TRUE(s.next(idle(), brick, rep));
    return telegramOf(Bytes(rep.bytes + 2, rep.bytes + rep.size));
  };
  ASSERT_TRUE(encodeMessageWrite(2, "explore", req));
  uint8_t status = 0xFF;
  ASSERT_TRUE(decodeMessageWriteReply(ask(req), status));
  EXPECT_EQ(status, kLegoOk);
  ASSERT_TRUE(encodeMessageRead(2, 0, true, req));
  char text[kLegoMaxMessage + 1];
  uint8_t box = 9;
  ASSERT_TRUE(decodeMessageReadReply(ask(req), status, box, text));
  EXPECT_EQ(status, kLegoOk);
  EXPECT_EQ(box, 0);
  EXPECT_STREQ(text, "explore");
  ASSERT_TRUE(encodeGetBatteryLevel(req));
  uint16_t mv = 0;
  ASSERT_TRUE(decodeBatteryReply(ask(req), status, mv));
  EXPECT_EQ(mv, 7980);
  ASSERT_TRUE(encodeKeepAlive(req));
  uint32_t sleep = 0;
  ASSERT_TRUE(decodeKeepAliveReply(ask(req), status, sleep));
  EXPECT_EQ(sleep, 60000u);
  EXPECT_FALSE(encodeMessageWrite(0, std::string(59, 'a').c_str(), req));  // 59 + NUL is too long
  EXPECT_TRUE(encodeMessageWrite(0, std::string(58, 'a').c_str(), req));
}

}  // namespace
}  // namespace nxtmap::protocol
