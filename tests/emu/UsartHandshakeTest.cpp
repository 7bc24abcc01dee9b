// The USART model's hardware handshaking at register level (SAM7S datasheet, USART "Hardware
// Handshaking"): with US_MR USMODE = 2 the RTS pin is high while the receiver is disabled or the PDC's
// RXBUFF is set (RCR = RNCR = 0, whatever PTCR says), and the peer does not send while it is high. So a
// firmware that receives byte by byte with the receive PDC idle gets nothing, and one that receives
// through the PDC gets every byte, the peer held back while both buffers are full.
#include "host/emu/Usart.hpp"

#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kCr = 0x00, kMr = 0x04, kCsr = 0x14, kBrgr = 0x20;
constexpr uint32_t kRpr = 0x100, kRcr = 0x104, kRnpr = 0x110, kRncr = 0x114, kPtcr = 0x120;
constexpr uint32_t kRxen = 1u << 4, kRxdis = 1u << 5, kRxrdy = 1u, kOvre = 1u << 5;
constexpr uint32_t kHandshake = 2u | (3u << 6) | (4u << 9) | (1u << 19), kNormal = kHandshake & ~0xFu;
constexpr uint32_t kRam = 0x200000;

struct Ram : GuestMemory {
  std::array<uint8_t, 1024> bytes{};
  bool readByte(uint32_t a, uint8_t& v) const override {
    if (a < kRam || a >= kRam + bytes.size()) return false;
    v = bytes[a - kRam];
    return true;
  }
  bool writeByte(uint32_t a, uint8_t v) override {
    if (a < kRam || a >= kRam + bytes.size()) return false;
    bytes[a - kRam] = v;
    return true;
  }
};

// A sender that obeys its CTS (the ARM's RTS) and records what it was told.
struct Sender : SerialPeer {
  std::deque<uint8_t> queue;
  bool cts = false;  // high = hold back
  void fromArm(uint8_t) override {}
  bool hasByteForArm() const override { return !cts && !queue.empty(); }
  uint8_t takeByteForArm() override {
    const uint8_t b = queue.front();
    queue.pop_front();
    return b;
  }
  void armRts(bool high) override { cts = high; }
};

struct Rig {
  Clock clock;
  Ram ram;
  Sender peer;
  Usart us{clock, ram, peer};
  Rig() { us.write(kBrgr, 13); }
  void run(uint64_t cycles) {
    const uint64_t end = clock.now + cycles;
    while (clock.now < end) {
      clock.now = std::min(end, std::max(clock.now + 1, us.nextEventAt() == kNever ? end : us.nextEventAt()));
      us.advanceTo(clock.now);
    }
  }
  uint32_t reg(uint32_t off) {
    uint32_t v = 0;
    us.read(off, v);
    return v;
  }
};

struct RtsRow {
  const char* what;
  uint32_t mode;
  bool rxEnabled, pdcEnabled;
  uint32_t rcr, rncr;
  bool rtsHigh;
};

TEST(UsartHandshake, RtsFollowsTheReceiverAndThePdcBuffers) {
  const RtsRow rows[] = {
      {"handshake, receiver off", kHandshake, false, true, 16, 16, true},
      {"handshake, no PDC buffer (byte-by-byte firmware)", kHandshake, true, false, 0, 0, true},
      {"handshake, PDC on but RCR = RNCR = 0", kHandshake, true, true, 0, 0, true},
      {"handshake, current buffer only", kHandshake, true, true, 16, 0, false},
      {"handshake, both buffers", kHandshake, true, true, 16, 16, false},
      {"handshake, buffer set but PDC disabled", kHandshake, true, false, 16, 0, false},
      {"normal mode, no buffer", kNormal, true, false, 0, 0, false},
  };
  for (const RtsRow& r : rows) {
    SCOPED_TRACE(r.what);
    Rig g;
    g.us.write(kMr, r.mode);
    g.us.write(kRpr, kRam);
    g.us.write(kRcr, r.rcr);
    g.us.write(kRnpr, kRam + 512);
    g.us.write(kRncr, r.rncr);
    g.us.write(kPtcr, r.pdcEnabled ? 1u : 2u);
    g.us.write(kCr, r.rxEnabled ? kRxen : kRxdis);
    EXPECT_EQ(g.us.rtsHigh(), r.rtsHigh);
    EXPECT_EQ(g.peer.cts, r.rtsHigh);
  }
}

// The old firmware's way: handshaking, receiver on, receive PDC idle, RXRDY polled. Nothing arrives.
TEST(UsartHandshake, ByteByByteReceptionWithoutThePdcGetsNothing) {
  Rig g;
  g.peer.queue = {0x03, 0x14, 0xFF, 0xE9};  // RESET_INDICATION
  g.us.write(kMr, kHandshake);
  g.us.write(kPtcr, 2u);  // RXTDIS
  g.us.write(kCr, kRxen);
  g.run(cyclesFromMs(5));
  EXPECT_EQ(g.reg(kCsr) & kRxrdy, 0u);
  EXPECT_EQ(g.peer.queue.size(), 4u);
  EXPECT_EQ(g.us.bytesReceived(), 0u);
}

// Through the PDC: 40 bytes into two 16-byte buffers; the sender stops after 32 (RTS high), a buffer
// handed back lets the rest in, in order.
TEST(UsartHandshake, PdcReceptionHoldsTheSenderBackWhileBothBuffersAreFull) {
  Rig g;
  for (int i = 0; i < 40; ++i) g.peer.queue.push_back(static_cast<uint8_t>(i + 1));
  g.us.write(kMr, kHandshake);
  g.us.write(kRpr, kRam);
  g.us.write(kRcr, 16);
  g.us.write(kRnpr, kRam + 16);
  g.us.write(kRncr, 16);
  g.us.write(kPtcr, 1u);
  g.us.write(kCr, kRxen);
  g.run(cyclesFromMs(5));
  EXPECT_EQ(g.us.bytesReceived(), 32u);
  EXPECT_TRUE(g.us.rtsHigh());
  EXPECT_FALSE(g.us.overrun());
  g.us.write(kRnpr, kRam + 32);  // a new buffer: RXBUFF clears, RTS falls
  g.us.write(kRncr, 16);
  EXPECT_FALSE(g.us.rtsHigh());
  g.run(cyclesFromMs(5));
  EXPECT_EQ(g.us.bytesReceived(), 40u);
  for (int i = 0; i < 40; ++i) EXPECT_EQ(g.ram.bytes[static_cast<size_t>(i)], i + 1) << i;
  EXPECT_EQ(g.reg(kRcr), 8u);
  EXPECT_EQ(g.reg(kCsr) & kOvre, 0u);
}

}  // namespace
}  // namespace nxtmap::emu::test
