// The byte-level codec: CRC, little-endian fields, packet layout, LEGO telegrams.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "common/protocol/ByteReader.hpp"
#include "common/protocol/ByteWriter.hpp"
#include "common/protocol/Crc32.hpp"
#include "common/protocol/LegoCommands.hpp"
#include "common/protocol/Packet.hpp"

namespace nxtmap::protocol {
namespace {

using Bytes = std::vector<uint8_t>;
Bytes bytesOf(const Frame& f) { return Bytes(f.bytes, f.bytes + f.size); }
Telegram telegramOf(const Bytes& b) {
  Telegram t;
  for (size_t i = 0; i < b.size(); ++i) t.bytes[i] = b[i];
  t.size = static_cast<uint8_t>(b.size());
  return t;
}

TEST(Crc32, MatchesTheStandardCheckValues) {
  struct Case {
    std::string text;
    uint32_t crc;
  };
  const Case cases[] = {{"", 0x00000000u},
                        {"a", 0xE8B7BE43u},
                        {"123456789", 0xCBF43926u},
                        {"The quick brown fox jumps over the lazy dog", 0x414FA339u}};
  for (const Case& c : cases) {
    EXPECT_EQ(crc32(reinterpret_cast<const uint8_t*>(c.text.data()), c.text.size()), c.crc) << c.text;
  }
}

TEST(ByteFields, AreLittleEndianAndBoundsChecked) {
  uint8_t buf[9] = {};
  ByteWriter w(buf, sizeof(buf));
  w.u8(0xA1);
  w.u16(0x1234);
  w.i16(-2);
  w.u32(0xDEADBEEFu);
  ASSERT_TRUE(w.ok());
  const Bytes expected = {0xA1, 0x34, 0x12, 0xFE, 0xFF, 0xEF, 0xBE, 0xAD, 0xDE};
  EXPECT_EQ(Bytes(buf, buf + 9), expected);
  w.u8(0);  // one byte too many
  EXPECT_FALSE(w.ok());

  ByteReader r(buf, sizeof(buf));
  EXPECT_EQ(r.u8(), 0xA1);
  EXPECT_EQ(r.u16(), 0x1234);
  EXPECT_EQ(r.i16(), -2);
  EXPECT_EQ(r.u32(), 0xDEADBEEFu);
  EXPECT_TRUE(r.ok() && r.atEnd());
  EXPECT_EQ(r.u8(), 0);
  EXPECT_FALSE(r.ok());
}

TEST(Packet, HasTheDocumentedLayout) {
  PacketHeader h;
  h.op = Op::Explore;
  h.flags = kFlagReliable;
  h.seq = 0x0102;
  h.ack = 0x0304;
  h.ackMask = 0x8001;
  const uint8_t payload[] = {0xAA, 0xBB};
  Frame f;
  ASSERT_TRUE(encodePacket(h, payload, sizeof(payload), f));
  const Bytes head = {16, 0, 0x4E, 0x02, kProtocolVersion, 0x01, 0x02, 0x01, 0x04, 0x03, 0x01, 0x80, 0xAA, 0xBB};
  ASSERT_EQ(f.size, 18);
  EXPECT_EQ(Bytes(f.bytes, f.bytes + 14), head);
  const uint32_t crc = crc32(f.bytes + 2, 12);
  EXPECT_EQ(Bytes(f.bytes + 14, f.bytes + 18),
            (Bytes{static_cast<uint8_t>(crc), static_cast<uint8_t>(crc >> 8), static_cast<uint8_t>(crc >> 16),
                   static_cast<uint8_t>(crc >> 24)}));

  Telegram t = telegramOf(Bytes(f.bytes + 2, f.bytes + f.size));
  ASSERT_TRUE(telegramValid(t.bytes, t.size));
  PacketView v;
  ASSERT_TRUE(parsePacket(t, v));
  EXPECT_EQ(v.header.op, Op::Explore);
  EXPECT_TRUE(v.header.reliable());
  EXPECT_EQ(v.header.seq, 0x0102);
  EXPECT_EQ(v.header.ack, 0x0304);
  EXPECT_EQ(v.header.ackMask, 0x8001);
  ASSERT_EQ(v.payloadSize, 2u);
  EXPECT_EQ(v.payload[1], 0xBB);
}

TEST(Packet, AnyFlippedBitFailsTheCheck) {
  PacketHeader h;
  h.op = Op::Status;
  uint8_t payload[40];
  for (int i = 0; i < 40; ++i) payload[i] = static_cast<uint8_t>(i * 7);
  Frame f;
  ASSERT_TRUE(encodePacket(h, payload, sizeof(payload), f));
  for (size_t byte = 2; byte < f.size; ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      Frame g = f;
      g.bytes[byte] ^= static_cast<uint8_t>(1u << bit);
      EXPECT_FALSE(telegramValid(g.bytes + 2, g.size - 2u)) << byte << ":" << bit;
    }
  }
}

TEST(Packet, RefusesPayloadsLargerThanTheBluetoothBuffer) {
  uint8_t payload[kMaxPayload + 1] = {};
  Frame f;
  PacketHeader h;
  EXPECT_TRUE(encodePacket(h, payload, kMaxPayload, f));
  EXPECT_EQ(f.size, kMaxFrame);
  EXPECT_FALSE(encodePacket(h, payload, kMaxPayload + 1, f));
}

TEST(SequenceNumbers, SkipZeroAndAcknowledgeThroughTheMask) {
  EXPECT_EQ(nextSeq(0), 1);
  EXPECT_EQ(nextSeq(41), 42);
  EXPECT_EQ(nextSeq(0xFFFF), 1);
  struct Case {
    uint16_t ack, mask, seq;
    bool acked;
  };
  const Case cases[] = {
      {10, 0x0000, 10, true},    {10, 0x0000, 9, false},  {10, 0x0001, 9, true},   {10, 0x8000, 26, false},
      {10, 0x8000, 65530, true}, {26, 0x8000, 10, true},  {26, 0x7FFF, 10, false}, {0, 0xFFFF, 0, false},
      {5, 0, 0, false},          {10, 0xFFFF, 11, false},
  };
  for (const Case& c : cases) EXPECT_EQ(acknowledges(c.ack, c.mask, c.seq), c.acked) << c.ack << " " << c.seq;
}

// LEGO direct commands, byte for byte as LEGO's Bluetooth developer kit lays them out.
TEST(LegoDirectCommands, AreAnsweredWithLegosReplyLayout) {
  Mailboxes boxes;
  struct Case {
    const char* what;
    Bytes command;
    Bytes reply;  // empty: no reply
  };
  const Case cases[] = {
      {"battery", {0x00, 0x0B}, {0x02, 0x0B, 0x00, 0x2C, 0x1F}},                 // 7980 mV
      {"keep alive", {0x00, 0x0D}, {0x02, 0x0D, 0x00, 0x60, 0xEA, 0x00, 0x00}},  // 60000 ms
      {"battery, no reply", {0x80, 0x0B}, {}},
      {"write box 3", {0x00, 0x09, 0x03, 0x03, 'h', 'i', 0x00}, {0x02, 0x09, 0x00}},
      {"write box 3 again, no reply", {0x80, 0x09, 0x03, 0x02, 'x', 0x00}, {}},
  };
  for (const Case& c : cases) {
    Frame reply;
    const bool answered = answerDirectCommand(telegramOf(c.command), boxes, 7980, 60000, reply);
    EXPECT_EQ(answered, !c.reply.empty()) << c.what;
    if (answered) {
      Bytes expected = {static_cast<uint8_t>(c.reply.size()), 0};
      expected.insert(expected.end(), c.reply.begin(), c.reply.end());
      EXPECT_EQ(bytesOf(reply), expected) << c.what;
    }
  }
  // MESSAGE_READ of remote box 13 (LEGO's outbox convention: box 3), removing: oldest first.
  Frame reply;
  ASSERT_TRUE(answerDirectCommand(telegramOf({0x00, 0x13, 13, 0, 1}), boxes, 0, 0, reply));
  ASSERT_EQ(reply.size, 2 + 64);
  EXPECT_EQ(Bytes(reply.bytes, reply.bytes + 10), (Bytes{64, 0, 0x02, 0x13, 0x00, 0, 3, 'h', 'i', 0}));
  ASSERT_TRUE(answerDirectCommand(telegramOf({0x00, 0x13, 3, 0, 1}), boxes, 0, 0, reply));
  EXPECT_EQ(Bytes(reply.bytes + 4, reply.bytes + 9), (Bytes{0x00, 0, 2, 'x', 0}));
  ASSERT_TRUE(answerDirectCommand(telegramOf({0x00, 0x13, 3, 0, 1}), boxes, 0, 0, reply));
  EXPECT_EQ(reply.bytes[4], kLegoMailboxEmpty);
}

TEST(LegoDirectCommands, MalformedOnesAreNotTelegrams) {
  const Bytes bad[] = {
      {0x00, 0x0B, 0x00},                 // battery with a stray byte
      {0x00, 0x09, 10, 2, 'a', 0},        // mailbox 10 does not exist
      {0x00, 0x09, 1, 3, 'a', 'b', 'c'},  // not NUL-terminated
      {0x00, 0x09, 1, 60, 0},             // size beyond 59 / mismatch
      {0x00, 0x13, 20, 0, 1},             // remote box 20
      {0x00, 0x13, 1, 0, 2},              // remove flag 2
      {0x00, 0x03, 0, 0, 0, 0, 0, 0},     // PLAY_TONE: not served
      {0x01, 0x9B},                       // system command: not served
      {0x4E, 0x02},                       // too short for a packet
  };
  for (const Bytes& b : bad) EXPECT_FALSE(telegramValid(b.data(), b.size())) << int(b[1]);
}

TEST(LegoDirectCommands, PcSideEncodersAndReplyDecodersRoundTrip) {
  Mailboxes boxes;
  Frame req, rep;
  ASSERT_TRUE(encodeMessageWrite(2, "explore", req));
  Telegram t = telegramOf(Bytes(req.bytes + 2, req.bytes + req.size));
  ASSERT_TRUE(answerDirectCommand(t, boxes, 0, 0, rep));
  uint8_t status = 0xFF;
  ASSERT_TRUE(decodeMessageWriteReply(telegramOf(Bytes(rep.bytes + 2, rep.bytes + rep.size)), status));
  EXPECT_EQ(status, kLegoOk);
  ASSERT_TRUE(encodeMessageRead(12, 0, true, req));
  ASSERT_TRUE(answerDirectCommand(telegramOf(Bytes(req.bytes + 2, req.bytes + req.size)), boxes, 0, 0, rep));
  char text[kLegoMaxMessage + 1];
  uint8_t box = 9;
  ASSERT_TRUE(decodeMessageReadReply(telegramOf(Bytes(rep.bytes + 2, rep.bytes + rep.size)), status, box, text));
  EXPECT_EQ(status, kLegoOk);
  EXPECT_EQ(box, 0);
  EXPECT_STREQ(text, "explore");
  ASSERT_TRUE(encodeGetBatteryLevel(req));
  ASSERT_TRUE(answerDirectCommand(telegramOf(Bytes(req.bytes + 2, req.bytes + req.size)), boxes, 8123, 0, rep));
  uint16_t mv = 0;
  ASSERT_TRUE(decodeBatteryReply(telegramOf(Bytes(rep.bytes + 2, rep.bytes + rep.size)), status, mv));
  EXPECT_EQ(mv, 8123);
  EXPECT_FALSE(encodeMessageWrite(0, std::string(59, 'a').c_str(), req));  // 59 + NUL is too long
  EXPECT_TRUE(encodeMessageWrite(0, std::string(58, 'a').c_str(), req));
}

}  // namespace
}  // namespace nxtmap::protocol
