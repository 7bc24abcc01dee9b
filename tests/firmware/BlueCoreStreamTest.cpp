// The BlueCore driver in stream mode: bytes received through the PDC while RTS lets the module send, and a link
// lost mid-transfer (also round the transmit ring's end) sending no stream byte as a command, then the next PC
// accepted.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "firmware/drivers/BlueCore.hpp"
#include "tests/firmware/Bc4Module.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {
using namespace reg;

// Boots the driver and takes a PC's connection up to stream mode.
template <class Bt>
void toStream(Bc4& m, Bt& bt, uint32_t& now) {
  bt.init(kMck, now);
  runMs(m, bt, now, 160);
  m.requestConnection();
  runMs(m, bt, now, 10);
  ASSERT_TRUE(bt.streaming());
}

// With handshaking the module may send only while a receive buffer is free: the driver arms both PDC
// buffers at init (RTS low), and in stream mode 1000 bytes pass in order though only 2 buffers fit at a time
// (RTS high while both buffers are full, low again once a buffer is read and handed back).
TEST(BlueCore, ReceivesThroughThePdcAndRtsLetsTheModuleSend) {
  {
    Bc4 fresh;
    BlueCore<FakeBus> idle(fresh.bus);
    idle.init(kMck, 0);
    EXPECT_TRUE(fresh.rxPdc);
    EXPECT_FALSE(fresh.rtsHigh());
    EXPECT_EQ(fresh.bus.regs[kUs1Rcr], UsartRxDma<FakeBus>::kBufferBytes);
    EXPECT_EQ(fresh.bus.regs[kUs1Rncr], UsartRxDma<FakeBus>::kBufferBytes);
  }
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  toStream(m, bt, now);
  ASSERT_TRUE(bt.streaming());
  std::vector<uint8_t> sent, got;
  for (int i = 0; i < 1000; ++i) sent.push_back(static_cast<uint8_t>(i * 7 + 3));
  m.toArm.insert(m.toArm.end(), sent.begin(), sent.end());
  for (int round = 0; round < 20 && got.size() < sent.size(); ++round) {
    m.deliver();
    if (round == 0) {
      EXPECT_TRUE(m.rtsHigh());  // both buffers full: the module holds back
      EXPECT_GE(m.toArm.size(), 1000u - 2u * UsartRxDma<FakeBus>::kBufferBytes);
    }
    uint8_t b;
    for (int k = 0; k < 100 && bt.readByte(b); ++k) got.push_back(b);  // a partial read, then more
    while (bt.readByte(b)) got.push_back(b);
  }
  EXPECT_EQ(got, sent);
  EXPECT_FALSE(m.rtsHigh());
}

TEST(BlueCore, LosingTheLinkMidTransferSendsNoStreamByteAsACommand) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  toStream(m, bt, now);
  m.holdTx = true;  // a frame for the PC is still being sent when the link drops
  const uint8_t frame[] = {0x02, 0x00, 0xAB, 0xCD};
  ASSERT_TRUE(bt.write(frame, 4));
  m.cmdLine = false;
  m.commands.clear();
  const size_t before = m.bus.writes.size();
  runMs(m, bt, now, 2);
  m.holdTx = false;
  m.releaseTx();
  runMs(m, bt, now, 5);
  EXPECT_TRUE(m.fromArm.empty()) << "the PC is gone: its frame is dropped";
  EXPECT_FALSE(m.badChecksum) << "a stream byte reached the module as part of a command";
  ASSERT_FALSE(m.commands.empty());
  for (const auto& c : m.commands) EXPECT_EQ(c[1], 0x03) << "only OPEN_PORT after the loss";
  // The transmitter stops before ARM7_CMD goes low.
  size_t stopAt = 0, lowAt = 0;
  for (size_t i = before; i < m.bus.writes.size(); ++i) {
    const auto& w = m.bus.writes[i];
    if (!stopAt && w.first == kUs1Ptcr && (w.second & (1u << 9))) stopAt = i;
    if (!lowAt && w.first == kPioCodr && (w.second & kPinBtArm7Cmd)) lowAt = i;
  }
  EXPECT_NE(stopAt, 0u);
  EXPECT_LT(stopAt, lowAt);
}

// A transfer round the transmit ring's end goes as two PDC buffers (TCR, then TNCR). Lost mid-way,
// neither buffer's rest may follow the next command: the PDC keeps both counters until they are
// written, and a stale TNCR would send old stream bytes behind OPEN_PORT, in command mode.
TEST(BlueCore, LosingTheLinkMidAWrappedTransferSendsNoStaleByteAfterTheNextCommand) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  toStream(m, bt, now);
  const std::array<uint8_t, 30> frame{0x1C, 0x00, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE,
                                      0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE};
  m.holdTx = true;  // frames for the PC, each still on its way, until one crosses the ring's end
  for (int i = 0; i < 40 && m.bus.regs[kUs1Tncr] == 0; ++i) {
    m.releaseTx();
    runMs(m, bt, now, 1);
    ASSERT_TRUE(bt.write(frame.data(), frame.size()));
  }
  ASSERT_NE(m.bus.regs[kUs1Tncr], 0u) << "a frame must go as two buffers";
  m.cmdLine = false;
  m.commands.clear();
  m.holdTx = false;
  runMs(m, bt, now, 5);
  EXPECT_FALSE(m.badChecksum) << "a stream byte reached the module as part of a command";
  EXPECT_TRUE(m.partial.empty()) << "stream bytes wait in the module as the start of a command";
  ASSERT_FALSE(m.commands.empty());
  for (const auto& c : m.commands) EXPECT_EQ(c[1], 0x03) << "only OPEN_PORT after the loss";
  m.requestConnection();
  runMs(m, bt, now, 10);
  EXPECT_TRUE(bt.streaming()) << "the next PC is accepted";
}

TEST(BlueCore, TheNextPcIsAcceptedAfterALinkLoss) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  toStream(m, bt, now);
  for (uint32_t pc = 1; pc <= 3; ++pc) {
    m.cmdLine = false;
    runMs(m, bt, now, 1);
    m.toArm.insert(m.toArm.end(), {0x05, 0x1A});  // the first bytes of a message cut by the link loss
    runMs(m, bt, now, 30);
    EXPECT_EQ(bt.linkEpoch(), pc);
    m.requestConnection();
    runMs(m, bt, now, 10);
    EXPECT_TRUE(bt.streaming()) << "PC " << pc + 1;
  }
}

}  // namespace
}  // namespace nxtmap::fw::test
