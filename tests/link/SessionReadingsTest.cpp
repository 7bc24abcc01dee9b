// The PC's Session and a house's readings: Scan goes out as a reliable command with its id (id 0
// refused), and the brick's Readings (the last standing scan) are kept as last reported; a malformed
// one changes nothing.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/Messages.hpp"
#include "common/protocol/Packet.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::link {
namespace {

using namespace protocol;

class SessionReadingsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    HelloReplyMsg r;
    r.session = 6;
    Payload p;
    encodeHelloReply(r, p);
    send(Op::HelloReply, p);
    ASSERT_TRUE(pc.connected());
  }
  void send(Op op, const Payload& p) {
    PacketHeader h;
    h.op = op;
    Frame f;
    ASSERT_TRUE(encodePacket(h, p.bytes, p.size, f));
    pc.receive(f.bytes, f.size, 0);
  }
  // The packets the PC sends now.
  std::vector<PacketView> sent(uint32_t nowMs) {
    out_ = pc.transmit(nowMs);
    std::vector<PacketView> v;
    FrameDecoder d;
    telegrams_.clear();
    for (uint8_t b : out_) d.push(b);
    Telegram t;
    while (d.pop(t)) telegrams_.push_back(t);
    for (const Telegram& x : telegrams_) {
      PacketView pv;
      if (parsePacket(x, pv)) v.push_back(pv);
    }
    return v;
  }

  Session pc{SessionConfig{6, 250, 250}};

 private:
  std::vector<uint8_t> out_;
  std::vector<Telegram> telegrams_;
};

ReadingsMsg readingsOf(uint16_t scanId, int16_t cm) {
  ReadingsMsg m;
  m.scanId = scanId;
  m.scanPose = Pose{Cell{2, 3}, Dir::West};
  for (RangeReading& r : m.scan) r = RangeReading{RangeStatus::Good, cm, 3};
  return m;
}

TEST_F(SessionReadingsTest, AScanGoesOutReliablyWithItsId) {
  EXPECT_THROW(pc.scan(0), std::invalid_argument);
  const uint16_t seq = pc.scan(0x1234);
  const std::vector<PacketView> v = sent(0);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_EQ(v[0].header.op, Op::Scan);
  EXPECT_TRUE(v[0].header.reliable());
  EXPECT_EQ(v[0].header.seq, seq);
  ScanMsg m;
  ASSERT_TRUE(decodeScan(v[0].payload, v[0].payloadSize, m));
  EXPECT_EQ(m.scanId, 0x1234);
}

TEST_F(SessionReadingsTest, TheLastReadingsAreKeptAndAMalformedOneChangesNothing) {
  EXPECT_FALSE(pc.readings().has_value());
  struct Step {
    const char* what;
    ReadingsMsg sent;
    bool spoil;          // the payload's scan pose heading set to 4: refused
    uint16_t scanAfter;  // the scan id the session holds after it
    int16_t cmAfter;     // and its readings' range
  };
  const Step steps[] = {
      {"the first", readingsOf(0, 40), false, 0, 40},
      {"a scan", readingsOf(7, 55), false, 7, 55},
      {"malformed", readingsOf(8, 66), true, 7, 55},
      {"the same again", readingsOf(7, 55), false, 7, 55},
  };
  for (const Step& s : steps) {
    Payload p;
    ASSERT_GT(encodeReadings(s.sent, p), 0u) << s.what;
    if (s.spoil) p.bytes[6] = 4;
    send(Op::Readings, p);
    ASSERT_TRUE(pc.readings().has_value()) << s.what;
    EXPECT_EQ(pc.readings()->scanId, s.scanAfter) << s.what;
    EXPECT_EQ(pc.readings()->scan[2].cm, s.cmAfter) << s.what;
  }
  EXPECT_EQ(pc.readings()->scanPose.heading, Dir::West);
}

}  // namespace
}  // namespace nxtmap::link
