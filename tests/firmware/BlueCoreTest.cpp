// The BlueCore driver from reset to a PC's connection: the UART's setup, RESET_INDICATION, the module's address,
// OPEN_PORT, ACCEPT_CONNECTION and OPEN_STREAM, noise fragments and the PIN request.
#include <gtest/gtest.h>

#include <array>
#include <deque>
#include <vector>

#include "firmware/drivers/BlueCore.hpp"
#include "tests/firmware/Bc4Module.hpp"
#include "tests/firmware/FakeBus.hpp"

namespace nxtmap::fw::test {
namespace {
using namespace reg;

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
