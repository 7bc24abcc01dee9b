// The byte-at-a-time decoder: every valid frame comes out, whatever noise surrounds it.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/Packet.hpp"
#include "common/protocol/SeqWindow.hpp"

namespace nxtmap::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

Bytes packetFrame(uint16_t seq, size_t payloadSize) {
  PacketHeader h;
  h.op = Op::MapDelta;
  h.flags = kFlagReliable;
  h.seq = seq;
  Bytes payload(payloadSize);
  for (size_t i = 0; i < payloadSize; ++i) payload[i] = static_cast<uint8_t>(seq * 31 + i);
  Frame f;
  EXPECT_TRUE(encodePacket(h, payload.data(), payload.size(), f));
  return Bytes(f.bytes, f.bytes + f.size);
}

// Feeds the stream byte by byte; returns the seqs of the packets delivered (LEGO telegrams as 1000+opcode).
std::vector<int> decodeAll(const Bytes& stream, FrameDecoder& d) {
  std::vector<int> out;
  Telegram t;
  for (uint8_t b : stream) {
    d.push(b);
    while (d.pop(t)) {
      PacketView v;
      if (parsePacket(t, v))
        out.push_back(v.header.seq);
      else
        out.push_back(1000 + t.opcode());
    }
  }
  return out;
}

Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

TEST(FrameDecoder, RecoversFromEveryKindOfDamage) {
  const Bytes a = packetFrame(1, 20), b = packetFrame(2, 100), c = packetFrame(3, 0);
  const Bytes battery = {2, 0, 0x00, 0x0B};
  auto dropAt = [](Bytes x, size_t i) {
    x.erase(x.begin() + static_cast<long>(i));
    return x;
  };
  auto flipAt = [](Bytes x, size_t i) {
    x[i] ^= 0x5A;
    return x;
  };
  auto dupAt = [](Bytes x, size_t i) {
    x.insert(x.begin() + static_cast<long>(i), x[i]);
    return x;
  };
  struct Case {
    std::string what;
    Bytes stream;
    std::vector<int> delivered;
  };
  const Case cases[] = {
      {"clean", concat({a, b, c}), {1, 2, 3}},
      {"leading noise", concat({{0xFF, 0x00, 0x4E, 0x13, 0x07}, a, b}), {1, 2}},
      {"LEGO command between packets", concat({a, battery, c}), {1, 1000 + 0x0B, 3}},
      {"byte dropped in the payload", concat({a, dropAt(b, 40), c}), {1, 3}},
      {"byte dropped in the length", concat({a, dropAt(b, 0), c}), {1, 3}},
      {"byte corrupted in the CRC", concat({a, flipAt(b, b.size() - 1), c}), {1, 3}},
      {"length corrupted to a large value", concat({flipAt(a, 0), b, c}), {2, 3}},
      {"byte duplicated", concat({a, dupAt(b, 7), c}), {1, 3}},
      {"frame duplicated whole", concat({a, a, c}), {1, 1, 3}},
      {"zero fill", concat({Bytes(300, 0), c}), {3}},
      {"0xFF fill", concat({Bytes(300, 0xFF), c}), {3}},
  };
  for (const Case& k : cases) {
    FrameDecoder d;
    EXPECT_EQ(decodeAll(k.stream, d), k.delivered) << k.what;
  }
}

// Telegrams of LEGO's types are consumed whole by their length, understood or not: each of these
// used to be resynchronised byte by byte, taking two of its bytes for a length (PLAY_TONE(300, 50)
// -> 50, SET_INPUT_MODE(ultrasonic) -> 11, MESSAGE_WRITE to inbox 12 -> 120) and swallowing what came
// next. After real damage only what can be checked is trusted until the decoder is back in step.
TEST(FrameDecoder, ConsumesEveryLegoTelegramWholeByItsLength) {
  const Bytes a = packetFrame(1, 20), b = packetFrame(2, 30), c = packetFrame(3, 0);
  const Bytes tone = {6, 0, 0x80, 0x03, 0x2C, 0x01, 0x32, 0x00};           // PLAY_TONE(300 Hz, 50 ms), no reply
  const Bytes inputMode = {5, 0, 0x80, 0x05, 0x00, 0x0B, 0x00};            // SET_INPUT_MODE(1, LOW_SPEED_9V, RAW)
  const Bytes write12 = {7, 0, 0x00, 0x09, 12, 3, 'h', 'i', 0};            // MESSAGE_WRITE(12, "hi")
  const Bytes stopProgram = {2, 0, 0x00, 0x01};                            // STOP_PROGRAM
  const Bytes lsWrite = {7, 0, 0x00, 0x0F, 0x00, 0x02, 0x01, 0x02, 0x42};  // LS_WRITE(1, [02 42], 1)
  Bytes openRead = {22, 0, 0x01, 0x80};                                    // system OPEN_READ("a.rxe")
  openRead.resize(24, 0);
  openRead[4] = 'a';
  const Bytes reply = {3, 0, 0x02, 0x05, 0xBE};  // a reply to the brick
  auto flipAt = [](Bytes x, size_t i) {
    x[i] ^= 0x5A;
    return x;
  };
  struct Case {
    std::string what;
    Bytes stream;
    std::vector<int> delivered;
  };
  const Case cases[] = {
      {"PLAY_TONE(300, 50)", concat({a, tone, b}), {1, 1000 + 0x03, 2}},
      {"SET_INPUT_MODE for an ultrasonic sensor", concat({a, inputMode, b}), {1, 1000 + 0x05, 2}},
      {"MESSAGE_WRITE to inbox 12", concat({a, write12, b}), {1, 1000 + 0x09, 2}},
      {"back to back, ours between",
       concat({stopProgram, lsWrite, a, openRead, reply, b}),
       {1000 + 0x01, 1000 + 0x0F, 1, 1000 + 0x80, 1000 + 0x05, 2}},
      {"first thing on the stream", concat({inputMode, c}), {1000 + 0x05, 3}},
      {"after damage an unknown command is not trusted", concat({a, flipAt(b, b.size() - 1), inputMode, c}), {1, 3}},
      {"after damage a known layout is", concat({a, flipAt(b, b.size() - 1), tone, c}), {1, 1000 + 0x03, 3}},
      {"and then the stream is trusted again",
       concat({flipAt(b, 5), tone, inputMode, c}),
       {1000 + 0x03, 1000 + 0x05, 3}},
  };
  for (const Case& k : cases) {
    FrameDecoder d;
    EXPECT_EQ(decodeAll(k.stream, d), k.delivered) << k.what;
  }
}

TEST(FrameDecoder, CountsWhatItThrowsAway) {
  FrameDecoder d;
  const Bytes noise = {0x01, 0x02, 0x03, 0x04, 0x05};
  const Bytes a = packetFrame(9, 10);
  decodeAll(concat({noise, a}), d);
  EXPECT_EQ(d.counters().bytes, noise.size() + a.size());
  EXPECT_EQ(d.counters().telegrams, 1u);
  EXPECT_EQ(d.counters().skipped, noise.size());
  EXPECT_EQ(d.buffered(), 0u);
}

TEST(FrameDecoder, AMaximumFrameFitsAndOneTooLongIsNoise) {
  FrameDecoder d;
  const Bytes big = packetFrame(5, kMaxPayload);
  ASSERT_EQ(big.size(), kMaxFrame);
  EXPECT_EQ(decodeAll(big, d), std::vector<int>{5});
  Bytes tooLong = big;
  tooLong[0] = static_cast<uint8_t>(kMaxTelegram + 1);
  tooLong.push_back(0);
  EXPECT_TRUE(decodeAll(concat({tooLong, packetFrame(6, 3)}), d) == std::vector<int>{6});
}

TEST(SeqWindow, RecordsNewSeqsAndRejectsRepeats) {
  struct Step {
    uint16_t seq;
    bool seenBefore;
    uint16_t ack, mask;  // after recording
  };
  const Step steps[] = {
      {5, false, 5, 0x0000},  {5, true, 5, 0x0000},    {6, false, 6, 0x0001},  {8, false, 8, 0x0006},
      {7, false, 8, 0x0007},  {7, true, 8, 0x0007},    {6, true, 8, 0x0007},   {30, false, 30, 0x0000},
      {13, true, 30, 0x0000}, {14, false, 30, 0x8000}, {14, true, 30, 0x8000}, {31, false, 31, 0x0001},
  };
  SeqWindow w;
  EXPECT_FALSE(w.seen(1));
  EXPECT_EQ(w.ack(), 0);
  for (const Step& s : steps) {
    EXPECT_EQ(w.seen(s.seq), s.seenBefore) << s.seq;
    w.record(s.seq);
    EXPECT_EQ(w.ack(), s.ack) << s.seq;
    EXPECT_EQ(w.ackMask(), s.mask) << s.seq;
    EXPECT_TRUE(w.seen(s.seq));
    if (static_cast<uint16_t>(w.ack() - s.seq) <= 16) {
      EXPECT_TRUE(acknowledges(w.ack(), w.ackMask(), s.seq));
    }
  }
  EXPECT_FALSE(w.seen(0));
}

TEST(SeqWindow, WrapsAroundSixtyFiveThousand) {
  SeqWindow w;
  uint16_t seq = 65530;
  for (int i = 0; i < 20; ++i) {
    EXPECT_FALSE(w.seen(seq));
    w.record(seq);
    seq = nextSeq(seq);
  }
  EXPECT_EQ(w.ack(), 14);
  EXPECT_TRUE(w.seen(65535));
  EXPECT_FALSE(w.seen(15));
}

}  // namespace
}  // namespace nxtmap::protocol
