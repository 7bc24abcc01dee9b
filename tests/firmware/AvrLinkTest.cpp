#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "firmware/drivers/AvrLink.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {
using namespace reg;

// The TWI controller plus the AVR behind it, at register level: with MREAD clear the first THR write
// opens a write transfer (bytes arrive through THR, TXRDY always set; the transfer ends by itself, so a
// STOP asked during a write is counted in `stopsInWrite`); with MREAD set a START opens a read whose
// bytes come from `reply` through RHR (RXRDY while bytes remain). TXCOMP is set while no transfer is
// active, and `txcompHeld` keeps it clear (a STOP still on the wire). `nackNext` answers the next
// transfer with NACK.
struct TwiAvr {
  FakeBus bus;
  std::vector<std::vector<uint8_t>> writes;  // completed write transfers
  std::vector<uint8_t> reply;                // the next 13-byte status frame
  size_t replyPos = 0;
  int reads = 0, startsInWrite = 0, stopsInWrite = 0;
  bool reading = false, active = false, nackNext = false, nacking = false, txcompHeld = false;

  uint32_t imr = 0;  // the TWI's interrupt mask (IER/IDR)

  void open() {
    EXPECT_EQ((bus.regs[kTwiMmr] >> 16) & 0x7F, 1u);  // AVR address
    // The TWI's interrupt line is SR & IMR; the AIC takes it on a rising edge, so a bit left enabled (TXRDY
    // stays set after a write) would hold it high and the next transfer's first RXRDY would make no edge.
    EXPECT_EQ(imr, 0u) << "a transfer started with TWI interrupts still enabled";
    EXPECT_FALSE(active) << "a transfer started before the last one ended";
    EXPECT_FALSE(txcompHeld) << "a transfer started before TXCOMP";
    active = true;
    nacking = nackNext;
    nackNext = false;
  }

  TwiAvr() {
    bus.onWrite = [this](uint32_t a, uint32_t v) {
      if (a == kTwiCr && (v & kTwiCrSwrst)) {  // a software reset clears the TWI's registers (SAM7S datasheet)
        bus.regs[kTwiCwgr] = bus.regs[kTwiMmr] = 0;
        imr = 0;
      }
      if (a == kTwiIer) imr |= v;
      if (a == kTwiIdr) imr &= ~v;
      const bool mread = (bus.regs[kTwiMmr] & kTwiMmrMread) != 0;
      if (a == kTwiCr && (v & kTwiCrStart)) {
        if (!mread) {
          ++startsInWrite;
          return;
        }
        open();
        reading = true;
        replyPos = 0;
        ++reads;
      }
      if (a == kTwiCr && (v & kTwiCrStop) && !mread) ++stopsInWrite;
      if (a == kTwiThr) {
        EXPECT_FALSE(mread);
        if (!active) {
          open();
          reading = false;
          writes.emplace_back();
        }
        writes.back().push_back(static_cast<uint8_t>(v));
      }
    };
    bus.onRead = [this](uint32_t a, uint32_t& v) {
      if (a == kTwiSr) {
        v = 0;
        if (!active) {
          v = txcompHeld ? 0 : kTwiSrTxcomp;
          return true;
        }
        if (nacking)
          v = kTwiSrNack;
        else if (reading)
          v = replyPos < reply.size() ? kTwiSrRxrdy : 0;
        else
          v = kTwiSrTxrdy;
        return true;
      }
      if (a == kTwiRhr) {
        v = replyPos < reply.size() ? reply[replyPos++] : 0;
        return true;
      }
      if (a == kPioPdsr) {
        v = kPinTwd;  // SDA idle high: no bus clearing needed
        return true;
      }
      return false;
    };
  }
  // Runs the TWI interrupt until the current transfer ends.
  template <class Link>
  void serve(Link& link) {
    for (int i = 0; i < 100 && active; ++i) {
      link.onInterrupt();
      if (bus.regs[kTwiIdr] == ~0u && !bus.writes.empty() && bus.writes.back().first == kTwiIdr) active = false;
    }
    active = false;
  }
  void setStatus(uint16_t buttons, uint16_t battery, bool corrupt = false) {
    reply.assign(13, 0);
    reply[8] = static_cast<uint8_t>(buttons);
    reply[9] = static_cast<uint8_t>(buttons >> 8);
    reply[10] = static_cast<uint8_t>(battery);
    reply[11] = static_cast<uint8_t>(battery >> 8);
    uint8_t s = 0;
    for (int i = 0; i < 12; ++i) s = static_cast<uint8_t>(s + reply[i]);
    reply[12] = static_cast<uint8_t>(0xFF - s + (corrupt ? 1 : 0));
  }
};

template <class Link>
void tickAndServe(TwiAvr& twi, Link& link, int ticks) {
  for (int i = 0; i < ticks; ++i) {
    link.tick();
    twi.serve(link);
  }
}

TEST(AvrLink, HandshakeThenAlternatingCommandAndStatusFrames) {
  TwiAvr twi;
  AvrLink<FakeBus> link(twi.bus);
  link.init();
  EXPECT_EQ(twi.bus.regs[kTwiCwgr], 57u | (57u << 8));  // 400 kHz
  twi.setStatus(0x320, 600);
  link.command().pwm[0] = 50;
  link.command().inputPower = 0xF0;
  tickAndServe(twi, link, 1);
  ASSERT_EQ(twi.writes.size(), 1u);
  ASSERT_EQ(twi.writes[0].size(), 47u);
  EXPECT_EQ(twi.writes[0][0], 0xCC);
  EXPECT_EQ(std::string(twi.writes[0].begin() + 1, twi.writes[0].end()),
            "Let's samba nxt arm in arm, (c)LEGO System A/S");
  tickAndServe(twi, link, 3);  // settle 2 ms: nothing on the bus
  EXPECT_EQ(twi.writes.size(), 1u);
  EXPECT_EQ(twi.reads, 0);
  constexpr int kP = AvrLink<FakeBus>::kTransferPeriodMs;
  tickAndServe(twi, link, 1);  // the first command right after the pause
  ASSERT_EQ(twi.writes.size(), 2u);
  tickAndServe(twi, link, kP - 1);
  EXPECT_EQ(twi.reads, 0);              // then one transfer every kTransferPeriodMs
  tickAndServe(twi, link, 1 + 2 * kP);  // read, write, read
  ASSERT_EQ(twi.writes.size(), 3u);
  EXPECT_EQ(twi.reads, 2);
  for (size_t w = 1; w < 3; ++w) {
    ASSERT_EQ(twi.writes[w].size(), 9u);
    uint8_t s = 0;
    for (uint8_t b : twi.writes[w]) s = static_cast<uint8_t>(s + b);
    EXPECT_EQ(s, 0xFF);
    EXPECT_EQ(twi.writes[w][2], 50);
    EXPECT_EQ(twi.writes[w][7], 0xF0);
  }
  EXPECT_TRUE(link.up());
  EXPECT_EQ(link.goodFrames(), 2u);
  EXPECT_EQ(link.status().buttonsRaw, 0x320);
  EXPECT_EQ(link.status().batteryRaw, 600);
  EXPECT_EQ(link.silentMs(), 0);
}

TEST(AvrLink, WritesStartAtTheirFirstByteAndEndByThemselvesReadsAskStop) {
  TwiAvr twi;
  AvrLink<FakeBus> link(twi.bus);
  link.init();
  twi.setStatus(0, 0);
  tickAndServe(twi, link, 5 + AvrLink<FakeBus>::kTransferPeriodMs);  // handshake, settle, write, read
  ASSERT_EQ(twi.writes.size(), 2u);
  EXPECT_EQ(twi.reads, 1);
  EXPECT_EQ(twi.startsInWrite, 0);  // LEGO's d_ioctrl.r: THR starts a write
  EXPECT_EQ(twi.stopsInWrite, 0);   // and the TWI ends it (THR and shifter empty)
  int stops = 0;
  for (uint32_t v : twi.bus.writesTo(kTwiCr)) stops += (v & kTwiCrStop) ? 1 : 0;
  EXPECT_EQ(stops, 1);  // the status read's, before its last byte
}

TEST(AvrLink, TheNextTransferWaitsForTxcomp) {
  TwiAvr twi;
  AvrLink<FakeBus> link(twi.bus);
  link.init();
  twi.setStatus(0, 0);
  tickAndServe(twi, link, 4);  // handshake + settle
  twi.txcompHeld = true;       // the handshake's STOP not yet sent
  tickAndServe(twi, link, 3 * AvrLink<FakeBus>::kTransferPeriodMs);
  EXPECT_EQ(twi.writes.size(), 1u);
  EXPECT_EQ(twi.reads, 0);
  twi.txcompHeld = false;
  tickAndServe(twi, link, 1);
  EXPECT_EQ(twi.writes.size(), 2u);  // the command goes as soon as TXCOMP is back
}

TEST(AvrLink, ThreeBadChecksumsInARowRestartWithTheHandshake) {
  TwiAvr twi;
  AvrLink<FakeBus> link(twi.bus);
  link.init();
  twi.setStatus(0, 0, true);
  tickAndServe(twi, link, 4);                                            // handshake + settle
  tickAndServe(twi, link, 1 + 5 * AvrLink<FakeBus>::kTransferPeriodMs);  // 3 writes + 3 bad reads
  EXPECT_EQ(link.badFrames(), 3u);
  EXPECT_EQ(link.restarts(), 1u);
  EXPECT_EQ(link.state(), AvrLink<FakeBus>::State::Down);
  tickAndServe(twi, link, 1);
  EXPECT_EQ(twi.writes.back().size(), 47u);  // handshake again
}

TEST(AvrLink, NackRestartsTheLink) {
  TwiAvr twi;
  AvrLink<FakeBus> link(twi.bus);
  link.init();
  twi.setStatus(0, 0);
  tickAndServe(twi, link, 4);
  twi.nackNext = true;
  tickAndServe(twi, link, 1);
  EXPECT_EQ(link.restarts(), 1u);
  EXPECT_FALSE(link.up());
}

// The reset that restarts the link clears the TWI's clock waveform with the rest: the link sets it again, as init did
// (left at 0 the TWI clocks bytes every 54 MCK cycles, each read overruns, and the link never comes back).
TEST(AvrLink, ARestartClocksTheTwiAsInitDid) {
  TwiAvr twi;
  AvrLink<FakeBus> link(twi.bus);
  link.init();
  const uint32_t clock = twi.bus.regs[kTwiCwgr];
  EXPECT_NE(clock, 0u);
  twi.setStatus(0, 0);
  tickAndServe(twi, link, 4);
  twi.nackNext = true;
  tickAndServe(twi, link, 1);
  ASSERT_EQ(link.restarts(), 1u);
  EXPECT_EQ(twi.bus.regs[kTwiCwgr], clock);
  tickAndServe(twi, link, 4 + 2 * AvrLink<FakeBus>::kTransferPeriodMs);  // handshake, settle, a command, a status
  EXPECT_TRUE(link.up());
  EXPECT_EQ(link.goodFrames(), 1u);
}

TEST(AvrLink, ATransferThatNeverEndsTimesOut) {
  TwiAvr twi;
  AvrLink<FakeBus> link(twi.bus);
  link.init();
  link.tick();  // starts the handshake; no interrupt ever serves it
  for (int i = 0; i < AvrLink<FakeBus>::kTimeoutMs; ++i) link.tick();
  EXPECT_EQ(link.restarts(), 1u);
}

}  // namespace
}  // namespace nxtmap::fw::test
