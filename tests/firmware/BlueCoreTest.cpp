#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <vector>

#include "firmware/drivers/BlueCore.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {
using namespace reg;

// USART1 + PDC + the BC4 module at register level. The module answers OPEN_PORT, ACCEPT_CONNECTION
// and OPEN_STREAM (raising its CMD line, read through ADC channel 6), checks the ARM's checksum rule,
// and while the ARM holds ARM7_CMD high exchanges raw bytes (data mode). A PDC transfer may be held
// (holdTx) to stand for bytes still on their way; TXTDIS abandons it, and its counters keep what was
// left (as the PDC's do: a transfer enabled later sends TCR bytes, then TNCR bytes from TNPR). Bytes to the ARM go through the
// receive PDC (RPR/RCR chained to RNPR/RNCR) and only while RTS is low: hardware handshaking holds RTS
// high while the receiver is off or RCR = RNCR = 0 (deliver()).
struct Bc4 {
  FakeBus bus;
  std::deque<uint8_t> toArm;
  std::vector<uint8_t> fromArm;                // raw bytes received (stream mode)
  std::vector<std::vector<uint8_t>> commands;  // command frames received (command mode)
  bool cmdLine = false, resetHeld = true, badChecksum = false, indicateReset = true, answerOpenPort = true;
  bool answerAddress = true;
  std::vector<uint8_t> localAddress{0x00, 0x16, 0x53, 0x12, 0x34, 0x56, 0x00};  // GET_LOCAL_ADDR_RESULT's 7 bytes
  bool armCmd = false;                                                          // ARM7_CMD (PA27): high = data mode
  bool holdTx = false;
  bool rxPdc = false;           // receive PDC enabled (PTCR RXTEN)
  std::vector<uint8_t> heldTx;  // a PDC transfer not sent yet
  std::vector<uint8_t> pinAnswer;

  Bc4() {
    bus.onRead = [this](uint32_t a, uint32_t& v) {
      if (a == kUs1Csr) {
        v = 0;
        return true;
      }
      if (a == kAdcCdr6) {
        v = cmdLine ? 0x3A0u : 0x010u;
        return true;
      }
      return false;
    };
    bus.onWrite = [this](uint32_t a, uint32_t v) {
      if (a == kPioSodr && (v & kPinBtArm7Cmd)) armCmd = true;
      if (a == kPioCodr && (v & kPinBtArm7Cmd)) armCmd = false;
      if (a == kUs1Ptcr && (v & (1u << 9))) heldTx.clear();     // TXTDIS: the transfer is abandoned
      if (a == kUs1Ptcr && (v & 1u)) rxPdc = true;              // RXTEN
      if (a == kUs1Ptcr && (v & 2u)) rxPdc = false;             // RXTDIS
      if (a == kUs1Rncr && v != 0 && bus.regs[kUs1Rcr] == 0) {  // the next buffer starts at once
        bus.regs[kUs1Rpr] = bus.regs[kUs1Rnpr];
        bus.regs[kUs1Rcr] = v;
        bus.regs[kUs1Rncr] = 0;
      }
      if (a == kPioCodr && (v & kPinBtReset)) resetHeld = true;
      if (a == kPioSodr && (v & kPinBtReset) && resetHeld) {
        resetHeld = false;
        if (indicateReset) reply(0x14, {});  // RESET_INDICATION
      }
      if (a == kUs1Ptcr && (v & (1u << 8))) {  // TXTEN: TCR bytes from TPR, then TNCR from TNPR
        const uint8_t* p = bus.pointer(bus.regs[kUs1Tpr]);
        heldTx.assign(p, p + bus.regs[kUs1Tcr]);
        if (bus.regs[kUs1Tncr] != 0) {
          const uint8_t* q = bus.pointer(bus.regs[kUs1Tnpr]);
          heldTx.insert(heldTx.end(), q, q + bus.regs[kUs1Tncr]);
        }
        if (!holdTx) releaseTx();
      }
    };
  }
  // RTS as the USART drives it in hardware-handshaking mode.
  bool rtsHigh() {
    const bool handshake = (bus.regs[kUs1Mr] & 0xFu) == 2u;
    return handshake && (!rxPdc || (bus.regs[kUs1Rcr] == 0 && bus.regs[kUs1Rncr] == 0));
  }
  // The module sends while RTS is low; each byte lands at RPR (the next buffer chained in at RCR 0).
  void deliver() {
    while (!toArm.empty() && !rtsHigh()) {
      auto* p = const_cast<uint8_t*>(bus.pointer(bus.regs[kUs1Rpr]));
      *p = toArm.front();
      toArm.pop_front();
      ++bus.regs[kUs1Rpr];
      if (--bus.regs[kUs1Rcr] == 0 && bus.regs[kUs1Rncr] != 0) {
        bus.regs[kUs1Rpr] = bus.regs[kUs1Rnpr];
        bus.regs[kUs1Rcr] = bus.regs[kUs1Rncr];
        bus.regs[kUs1Rncr] = 0;
      }
    }
  }
  void releaseTx() {
    const std::vector<uint8_t> bytes = std::move(heldTx);
    heldTx.clear();
    for (uint8_t b : bytes) received(b);
    bus.regs[kUs1Tcr] = 0;
    bus.regs[kUs1Tncr] = 0;
  }
  void reply(uint8_t code, std::vector<uint8_t> payload) {
    std::vector<uint8_t> f{static_cast<uint8_t>(payload.size() + 3), code};
    f.insert(f.end(), payload.begin(), payload.end());
    uint16_t sum = 0;
    for (uint8_t b : f) sum = static_cast<uint16_t>(sum + b);  // includes the length byte
    sum = static_cast<uint16_t>(0u - sum);
    f.push_back(static_cast<uint8_t>(sum >> 8));
    f.push_back(static_cast<uint8_t>(sum));
    toArm.insert(toArm.end(), f.begin(), f.end());
  }
  std::vector<uint8_t> partial;
  void received(uint8_t b) {
    if (armCmd) {
      fromArm.push_back(b);
      return;
    }
    partial.push_back(b);
    if (partial.size() < 2 || partial.size() < static_cast<size_t>(partial[0]) + 1) return;
    std::vector<uint8_t> f;
    f.swap(partial);
    uint16_t sum = 0;
    for (size_t i = 1; i + 2 < f.size(); ++i) sum = static_cast<uint16_t>(sum + f[i]);  // length excluded
    const uint16_t got = static_cast<uint16_t>((f[f.size() - 2] << 8) | f.back());
    if (static_cast<uint16_t>(sum + got) != 0) {
      badChecksum = true;
      return;
    }
    commands.push_back(f);
    const uint8_t code = f[1];
    if (code == 0x27 && answerAddress) reply(0x28, localAddress);   // GET_LOCAL_ADDR
    if (code == 0x03 && answerOpenPort) reply(0x1B, {0x01, 0x00});  // PORT_OPEN_RESULT: open
    if (code == 0x09 && f[2] == 1) reply(0x13, {0x01, 0x05});       // CONNECT_RESULT: ok, handle 5
    if (code == 0x0B && f[2] == 5) cmdLine = true;                  // OPEN_STREAM(5)
    if (code == 0x0A) pinAnswer.assign(f.begin() + 2, f.end() - 2);
  }
  void requestConnection() { reply(0x16, {1, 2, 3, 4, 5, 6, 0}); }
  bool sawCommand(uint8_t code) const {
    for (const auto& c : commands)
      if (c[1] == code) return true;
    return false;
  }
};

template <class Bt>
void runMs(Bc4& m, Bt& bt, uint32_t& now, uint32_t ms) {
  for (uint32_t i = 0; i < ms; ++i, ++now) {
    m.deliver();
    bt.poll(now);
  }
}

TEST(BlueCore, UartSetupUsesHardwareHandshakeAndLeavesPa23Alone) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  bt.init(kMck, 0);
  EXPECT_EQ(m.bus.regs[kUs1Mr], 0x000808C2u);  // USMODE 2, CHRL 8 bit, PAR none (4), OVER
  EXPECT_EQ(m.bus.regs[kUs1Brgr], 13u);
  for (uint32_t v : m.bus.writesTo(kPioPdr)) EXPECT_EQ(v & pin(23), 0u);
  EXPECT_EQ(m.bus.regs[kPioPdr], kPinBtRxd | kPinBtTxd | kPinBtRts | kPinBtCts);
  // Clocks for the USART, the PIO and the ADC that reads the module's CMD line.
  EXPECT_EQ(m.bus.regs[kPmcPcer], (1u << kIdUsart1) | (1u << kIdPioa) | (1u << kIdAdc));
}

TEST(BlueCore, FromResetToStreamModeOnAnIncomingConnection) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  bt.init(kMck, now);
  runMs(m, bt, now, 50);
  EXPECT_TRUE(m.resetHeld);  // reset held low for 100 ms
  runMs(m, bt, now, 100);
  EXPECT_FALSE(m.resetHeld);
  runMs(m, bt, now, 10);
  EXPECT_TRUE(m.sawCommand(0x03));  // OPEN_PORT after RESET_INDICATION
  EXPECT_EQ(bt.state(), BlueCore<FakeBus>::State::Listening);
  m.requestConnection();
  runMs(m, bt, now, 10);
  EXPECT_TRUE(m.sawCommand(0x09));  // ACCEPT_CONNECTION
  EXPECT_TRUE(m.sawCommand(0x0B));  // OPEN_STREAM(handle)
  EXPECT_TRUE(bt.streaming());
  EXPECT_FALSE(m.badChecksum);
  // ARM7_CMD (PA27) went high to enter data mode.
  EXPECT_NE(m.bus.writesTo(kPioSodr).back() & kPinBtArm7Cmd, 0u);

  // Stream mode: raw bytes both ways.
  const uint8_t hello[] = {0x02, 0x00, 0xAB, 0xCD};
  ASSERT_TRUE(bt.write(hello, 4));
  EXPECT_EQ(m.fromArm, (std::vector<uint8_t>{0x02, 0x00, 0xAB, 0xCD}));
  m.toArm.insert(m.toArm.end(), {0x01, 0x00, 0x7E});
  m.deliver();
  std::vector<uint8_t> got;
  uint8_t b;
  while (bt.readByte(b)) got.push_back(b);
  EXPECT_EQ(got, (std::vector<uint8_t>{0x01, 0x00, 0x7E}));

  // The PC goes away: CMD line low -> command mode, port opened again.
  m.cmdLine = false;
  m.commands.clear();
  runMs(m, bt, now, 5);
  EXPECT_FALSE(bt.streaming());
  EXPECT_EQ(bt.linkEpoch(), 1u);
  EXPECT_NE(m.bus.writesTo(kPioCodr).back() & kPinBtArm7Cmd, 0u);
  EXPECT_TRUE(m.sawCommand(0x03));
  EXPECT_FALSE(bt.write(hello, 4));
}

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

TEST(BlueCore, AConnectionRequestWhileThePortOpensIsAccepted) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  m.answerOpenPort = false;  // PORT_OPEN_RESULT still on its way when the PC dials in
  bt.init(kMck, now);
  runMs(m, bt, now, 160);
  ASSERT_TRUE(m.sawCommand(0x03));
  ASSERT_EQ(bt.state(), BlueCore<FakeBus>::State::OpenPort);
  m.requestConnection();
  runMs(m, bt, now, 10);
  EXPECT_TRUE(m.sawCommand(0x09));  // ACCEPT_CONNECTION
  EXPECT_TRUE(bt.streaming());
}

// A fragment (a length byte, then nothing) is dropped after kMessageGapMs, so the messages after it
// are read; a message whose bytes straddle main-loop passes is still taken whole.
TEST(BlueCore, ANoiseFragmentDoesNotSwallowTheMessagesAfterIt) {
  struct Case {
    std::vector<uint8_t> fragment;
    uint32_t silenceMs;
  };
  const std::vector<Case> cases{
      {{0x1B}, BlueCore<FakeBus>::kMessageGapMs},                 // a length of 27, then silence
      {{0x23, 0x99}, 50},                                         // the longest length
      {{0x0A, 0x16, 1, 2, 3}, BlueCore<FakeBus>::kMessageGapMs},  // half of a message
  };
  for (const Case& c : cases) {
    Bc4 m;
    BlueCore<FakeBus> bt(m.bus);
    uint32_t now = 0;
    bt.init(kMck, now);
    runMs(m, bt, now, 160);
    ASSERT_EQ(bt.state(), BlueCore<FakeBus>::State::Listening);
    m.toArm.insert(m.toArm.end(), c.fragment.begin(), c.fragment.end());
    runMs(m, bt, now, c.silenceMs + 1);
    m.requestConnection();
    runMs(m, bt, now, 10);
    EXPECT_TRUE(m.sawCommand(0x09)) << "after a fragment of " << c.fragment.size() << " bytes";
  }
  // Straddling passes: REQUEST_CONNECTION in two halves, 3 ms apart.
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  bt.init(kMck, now);
  runMs(m, bt, now, 160);
  m.requestConnection();
  std::deque<uint8_t> rest(m.toArm.begin() + 5, m.toArm.end());
  m.toArm.resize(5);
  runMs(m, bt, now, 3);
  m.toArm = rest;
  runMs(m, bt, now, 10);
  EXPECT_TRUE(m.sawCommand(0x09));
}

TEST(BlueCore, AnswersAPinRequestWith1234) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  bt.init(kMck, now);
  runMs(m, bt, now, 120);
  m.reply(0x15, {9, 8, 7, 6, 5, 4, 0});  // REQUEST_PIN_CODE
  runMs(m, bt, now, 2);
  ASSERT_EQ(m.pinAnswer.size(), 23u);
  EXPECT_EQ(m.pinAnswer[0], 9);
  EXPECT_EQ(m.pinAnswer[7], '1');
  EXPECT_EQ(m.pinAnswer[10], '4');
  EXPECT_EQ(m.pinAnswer[11], 0);
}

// At start-up, before the port opens, the driver asks the module for its address (GET_LOCAL_ADDR,
// no payload) and keeps the answer's first 6 bytes, most significant first; a module that does not
// answer within kReplyMs leaves the address zeros and the port is opened all the same.
TEST(BlueCore, AsksTheModuleForItsAddressBeforeOpeningThePort) {
  struct Row {
    const char* what;
    bool answer;
    std::vector<uint8_t> reported;  // GET_LOCAL_ADDR_RESULT's payload
    std::array<uint8_t, 6> kept;
    bool openAtOnce;  // OPEN_PORT follows the answer at once, else only after kReplyMs
  };
  constexpr uint32_t kReleased = 100, kGiveUp = kReleased + BlueCore<FakeBus>::kReplyMs;
  const std::vector<Row> rows{
      {"LEGO's OUI", true, {0x00, 0x16, 0x53, 0x12, 0x34, 0x56, 0x00}, {0x00, 0x16, 0x53, 0x12, 0x34, 0x56}, true},
      {"all ones", true, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}, {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}, true},
      {"too short: ignored", true, {0x00, 0x16, 0x53}, {0, 0, 0, 0, 0, 0}, false},
      {"no answer", false, {}, {0, 0, 0, 0, 0, 0}, false},
  };
  for (const Row& r : rows) {
    Bc4 m;
    m.answerAddress = r.answer;
    m.localAddress = r.reported;
    BlueCore<FakeBus> bt(m.bus);
    uint32_t now = 0;
    bt.init(kMck, now);
    runMs(m, bt, now, kReleased + 10);
    ASSERT_FALSE(m.commands.empty()) << r.what;
    EXPECT_EQ(m.commands.front(), (std::vector<uint8_t>{0x03, 0x27, 0xFF, 0xD9})) << r.what;  // len, code, sum
    runMs(m, bt, now, kGiveUp - 5 - now);
    EXPECT_EQ(m.sawCommand(0x03), r.openAtOnce) << r.what;
    runMs(m, bt, now, 10);
    EXPECT_TRUE(m.sawCommand(0x03)) << r.what;
    std::array<uint8_t, 6> kept{};
    for (size_t i = 0; i < 6; ++i) kept[i] = bt.address()[i];
    EXPECT_EQ(kept, r.kept) << r.what;
  }
}

TEST(BlueCore, WithoutResetIndicationItOpensThePortAfterFiveSeconds) {
  Bc4 m;
  BlueCore<FakeBus> bt(m.bus);
  uint32_t now = 0;
  m.indicateReset = false;  // the indication gets lost
  bt.init(kMck, now);
  runMs(m, bt, now, 4000);
  EXPECT_FALSE(m.sawCommand(0x03));
  runMs(m, bt, now, 1200);  // 5 s after the reset was released at 100 ms
  EXPECT_TRUE(m.sawCommand(0x03));
}

}  // namespace
}  // namespace nxtmap::fw::test
