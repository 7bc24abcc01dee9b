// The byte-level codec: CRC, little-endian fields, packet layout, LEGO telegrams.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "common/protocol/ByteReader.hpp"
#include "common/protocol/ByteWriter.hpp"
#include "common/protocol/Crc32.hpp"
#include "common/protocol/Packet.hpp"

namespace nxtmap::protocol {
namespace {

using Bytes = std::vector<uint8_t>;
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

// LEGO's commands: LegoServerTest.cpp.

}  // namespace
}  // namespace nxtmap::protocol
