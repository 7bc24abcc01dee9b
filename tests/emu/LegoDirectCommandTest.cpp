// LEGO's direct and system commands, as a PC tool sends them (LegoClient: the Bluetooth Developer Kit's tables,
// not our encoder), against the real firmware image in the emulated brick: each reply's layout and status, in
// order, without a stall. Tables of requests and the replies LEGO's protocol gives them.
#include "LegoBrickSession.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace nxtmap::emu::lego {
namespace {

struct Row {
  const char* what;
  Bytes request;
  bool withPrevious;
  uint8_t status;
  std::function<void(const Reply&)> fields;  // checks of the reply's own fields (null: none)
};

void skipUnlessRunnable() {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "the emulated brick at ASan speed: make test runs this from the Release build (EndToEnd)";
#endif
}

// Sends the rows in order and checks each reply: type 0x02, the request's opcode, the kit's size, the status.
void expectRows(const std::vector<Row>& rows, const SessionOptions& o = {}) {
  if (simFirmwarePath().empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  std::vector<Step> script;
  for (const Row& r : rows) script.push_back({r.request, r.withPrevious});
  const SessionResult s = runSession(script, o);
  ASSERT_EQ(s.error, "");
  ASSERT_EQ(s.exchanges.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    const Exchange& e = s.exchanges[i];
    SCOPED_TRACE(std::to_string(i) + ": " + rows[i].what);
    if (replySize(e.request) == 0) continue;
    ASSERT_TRUE(e.answered) << "no reply within " << o.replyTimeoutMs << " ms";
    EXPECT_EQ(e.reply.type(), kReply);
    EXPECT_EQ(e.reply.opcode(), e.request[1]);
    const size_t size = rows[i].status == kUnknownOpcode ? 3 : replySize(e.request);  // unknown: status only
    EXPECT_EQ(e.reply.bytes.size(), size);
    EXPECT_EQ(e.reply.status(), rows[i].status);
    if (rows[i].fields && e.reply.bytes.size() == size) rows[i].fields(e.reply);
  }
  EXPECT_EQ(s.extraReplies, 0u);
}

// What the firmware answers today: the four commands it has served since protocol 1.
TEST(LegoDirectCommandsEndToEnd, TheFourServedCommandsAnswerWithLegosLayoutAndStatus) {
  skipUnlessRunnable();
  const std::vector<Row> rows = {
      {"battery", getBatteryLevel(), false, kSuccess,
       [](const Reply& r) {
         EXPECT_GT(r.u16(3), 0u);
         EXPECT_LT(r.u16(3), 12000u) << "millivolts";
       }},
      {"keep alive", keepAlive(), false, kSuccess, nullptr},
      {"write inbox 0", messageWrite(0, "hello"), false, kSuccess, nullptr},
      {"read it back, removed", messageRead(0, 0, true), false, kSuccess,
       [](const Reply& r) {
         EXPECT_EQ(r.u8(3), 0u) << "local inbox";
         EXPECT_EQ(r.u8(4), 6u) << "size with the NUL";
         EXPECT_EQ(r.text(5, 59), "hello");
       }},
      {"inbox 0 now empty", messageRead(0, 0, true), false, kMailboxEmpty, nullptr},
      {"write inbox 3 without a reply", messageWrite(3, "no reply", false), false, kSuccess, nullptr},
      {"read inbox 3, kept", messageRead(3, 3, false), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.text(5, 59), "no reply"); }},
      {"read inbox 3 again, removed", messageRead(3, 3, true), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.text(5, 59), "no reply"); }},
      {"58 characters", messageWrite(9, std::string(58, 'z')), false, kSuccess, nullptr},
      {"read 58 characters", messageRead(9, 9, true), false, kSuccess,
       [](const Reply& r) {
         EXPECT_EQ(r.u8(4), 59u);
         EXPECT_EQ(r.text(5, 59), std::string(58, 'z'));
       }},
  };
  expectRows(rows);
}

// Round trips of the served commands at idle: each within the target of issue 20 (60 ms), no stall.
TEST(LegoDirectCommandsEndToEnd, ServedCommandsAnswerWithin60MsAtIdle) {
  skipUnlessRunnable();
  if (simFirmwarePath().empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  std::vector<Step> script;
  for (int i = 0; i < 40; ++i) script.push_back({i % 2 ? keepAlive() : getBatteryLevel(), false});
  const SessionResult s = runSession(script, {});
  ASSERT_EQ(s.error, "");
  double worst = 0;
  for (const Exchange& e : s.exchanges) {
    ASSERT_TRUE(e.answered);
    worst = std::max(worst, e.roundTripMs());
  }
  EXPECT_LE(worst, 60.0) << "slowest round trip, emulated ms";
}

// --- Issue 20's commands (the firmware side is being built; DISABLED_ rows are its open expectations). ---

TEST(LegoDirectCommandsEndToEnd, VersionAndDeviceInfoAnswerWithLegosLayout) {
  skipUnlessRunnable();
  const std::vector<Row> rows = {
      {"firmware version", getFirmwareVersion(), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.u8(4), 1u) << "protocol major (LEGO's is 1)"; }},
      {"device info", getDeviceInfo(), false, kSuccess,
       [](const Reply& r) {
         EXPECT_FALSE(r.text(3, 15).empty()) << "brick name";
         EXPECT_EQ(r.u8(3 + 14), 0u) << "name NUL-terminated within 15 bytes";
       }},
  };
  expectRows(rows);
}

// The module's address (the firmware asks the emulated BC4 with GET_LOCAL_ADDR at start-up; it answers
// 00:16:53:0E:4D:5A) in LEGO's order, most significant byte first, and the flash the image leaves free.
TEST(LegoDirectCommandsEndToEnd, DeviceInfoReportsAddressAndFreeFlash) {
  skipUnlessRunnable();
  expectRows({{"device info", getDeviceInfo(), false, kSuccess, [](const Reply& r) {
                 const std::vector<uint8_t> address{r.u8(18), r.u8(19), r.u8(20), r.u8(21), r.u8(22), r.u8(23)};
                 EXPECT_EQ(address, (std::vector<uint8_t>{0x00, 0x16, 0x53, 0x0E, 0x4D, 0x5A})) << "Bluetooth address";
                 EXPECT_GT(r.u32(29), 0u) << "free user flash";
               }}});
}

TEST(LegoDirectCommandsEndToEnd, SensorsAndMotorsAnswerWithLegosLayout) {
  skipUnlessRunnable();
  const std::vector<Row> rows = {
      {"input values, port 1 (ultrasonic)", getInputValues(0), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.u8(3), 0u) << "port"; }},
      {"input values, port 4", getInputValues(3), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.u8(3), 3u) << "port"; }},
      {"output state, port A", getOutputState(0), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.u8(3), 0u) << "port"; }},
      {"output state, port C", getOutputState(2), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.u8(3), 2u) << "port"; }},
      {"reset motor position A (idle)", resetMotorPosition(0, false), false, kSuccess, nullptr},
      {"play tone 440 Hz 50 ms", playTone(440, 50), false, kSuccess, nullptr},
  };
  expectRows(rows);
}

TEST(LegoDirectCommandsEndToEnd, APortOutOfRangeIsRefused) {
  skipUnlessRunnable();
  const std::vector<Row> rows = {
      {"input values, port 5", getInputValues(4), false, kOutOfRange, nullptr},
      {"output state, port D", getOutputState(3), false, kOutOfRange, nullptr},
  };
  expectRows(rows);
}

// Every other command that asks for a reply gets LEGO's "unknown command opcode" (0xBE, status only) at once.
TEST(LegoDirectCommandsEndToEnd, UnservedCommandsGetTheUnknownCommandStatus) {
  skipUnlessRunnable();
  const std::vector<Row> rows = {
      {"stop program", stopProgram(), false, kUnknownOpcode, nullptr},
      {"current program name", getCurrentProgramName(), false, kUnknownOpcode, nullptr},
      {"LS get status", lsGetStatus(0), false, kUnknownOpcode, nullptr},
      {"an opcode LEGO does not have", Bytes{kDirect, 0x7E}, false, kUnknownOpcode, nullptr},
      {"a system opcode we do not serve", Bytes{kSystem, 0x94, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0}, false, kUnknownOpcode,
       nullptr},
      {"still in step: battery", getBatteryLevel(), false, kSuccess, nullptr},
  };
  expectRows(rows);
}

// Inboxes 0..19 (issue 20); a message to inbox 20 is refused with LEGO's illegal-mailbox status.
TEST(LegoDirectCommandsEndToEnd, InboxesBeyond19AreRefused) {
  skipUnlessRunnable();
  const std::vector<Row> rows = {
      {"write inbox 12", messageWrite(12, "x"), false, kSuccess, nullptr},
      {"read inbox 12", messageRead(12, 0, true), false, kSuccess,
       [](const Reply& r) { EXPECT_EQ(r.text(5, 59), "x"); }},
      {"write inbox 20", messageWrite(20, "x"), false, kIllegalMailbox, nullptr},
  };
  expectRows(rows);
}

// Commands the brick does not serve and that ask for no reply leave no trace: the next reply is the next
// request's. PLAY_TONE(300, 50) and SET_INPUT_MODE once desynchronised the decoder (issue 20).
TEST(LegoDirectCommandsEndToEnd, NoReplyCommandsAreConsumedWholeByTheirLength) {
  skipUnlessRunnable();
  const std::vector<Row> rows = {
      {"tone, no reply", playTone(300, 50, false), false, kSuccess, nullptr},
      {"battery after it", getBatteryLevel(), true, kSuccess, nullptr},
      {"ultrasonic mode, no reply", setInputMode(0, 0x0B, 0x00, false), false, kSuccess, nullptr},
      {"keep alive after it", keepAlive(), true, kSuccess, nullptr},
      {"inbox 12, no reply", messageWrite(12, "x", false), false, kSuccess, nullptr},
      {"battery after it", getBatteryLevel(), true, kSuccess, nullptr},
  };
  expectRows(rows);
}

// 1000 mixed requests, some back to back, some for commands we do not implement: each answered, in order,
// none later than the time-out.
TEST(LegoDirectCommandsEndToEnd, AThousandMixedRequestsAreEachAnsweredInOrder) {
  skipUnlessRunnable();
  if (simFirmwarePath().empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  std::vector<Step> script;
  uint32_t x = 12345;
  for (int i = 0; i < 1000; ++i) {
    x = x * 1103515245u + 12345u;
    const uint32_t pick = (x >> 16) % 8;
    const bool backToBack = ((x >> 8) & 3) == 0 && i > 0;
    Bytes r = pick == 0   ? getBatteryLevel()
              : pick == 1 ? keepAlive()
              : pick == 2 ? messageWrite(static_cast<uint8_t>(i % 10), "m" + std::to_string(i))
              : pick == 3 ? messageRead(static_cast<uint8_t>(i % 10), 0, true)
              : pick == 4 ? Bytes{kDirect, 0x7E}  // unknown
              : pick == 5 ? lsGetStatus(1)        // not served: unknown command
              : pick == 6 ? playTone(500, 10, false)
                          : getFirmwareVersion();
    script.push_back({r, backToBack});
  }
  SessionOptions o;
  o.maxSeconds = 300;
  const SessionResult s = runSession(script, o);
  ASSERT_EQ(s.error, "");
  size_t missing = 0, wrong = 0;
  double worst = 0;
  for (const Exchange& e : s.exchanges) {
    if (replySize(e.request) == 0) continue;
    if (!e.answered) {
      ++missing;
      continue;
    }
    const bool unserved = e.request[1] == 0x7E || e.request[1] == kLsGetStatus;
    const size_t size = unserved ? 3 : replySize(e.request);
    if (e.reply.opcode() != e.request[1] || e.reply.bytes.size() != size) ++wrong;
    if (unserved && e.reply.status() != kUnknownOpcode) ++wrong;
    worst = std::max(worst, e.roundTripMs());
  }
  EXPECT_EQ(missing, 0u);
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(s.extraReplies, 0u);
  EXPECT_LE(worst, 100.0) << "slowest round trip, emulated ms";
}

// Each reply reaches the PC in one radio packet (a tool that reads the length and then the body in one read
// gets it whole): no telegram is cut across two of the BlueCore's bursts, also where the firmware's transmit
// ring wraps (512 bytes: every 30-50 replies): the transmit hands the wrapped part to the PDC as its next
// buffer (TNPR/TNCR), shifted out back to back. Without that it left as two PDC buffers a main-loop pass
// apart, and nxt-python's devfile backend read half a reply.
TEST(LegoDirectCommandsEndToEnd, EveryReplyArrivesInOneRadioPacket) {
  skipUnlessRunnable();
  if (simFirmwarePath().empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  std::vector<Step> script;
  for (int i = 0; i < 300; ++i)
    script.push_back({i % 3 == 0 ? messageRead(1, 1, false) : i % 3 == 1 ? getOutputState(0) : keepAlive(), false});
  const SessionResult s = runSession(script, {});
  ASSERT_EQ(s.error, "");
  EXPECT_GE(s.packets, 300u);
  EXPECT_EQ(s.cutTelegrams, 0u) << "of " << s.packets << " packets";
}

// While the robot explores, the radio is served within issue 20's target (100 ms).
TEST(LegoDirectCommandsEndToEnd, ServedCommandsAnswerWithin100MsWhileDriving) {
  skipUnlessRunnable();
  if (simFirmwarePath().empty()) GTEST_SKIP() << "no nxtmap-sim.elf";
  std::vector<Step> script;
  for (int i = 0; i < 100; ++i) script.push_back({getBatteryLevel(), false});
  SessionOptions o;
  o.drive = true;
  o.startAtS = 3.0;
  o.gapMs = 20;
  const SessionResult s = runSession(script, o);
  ASSERT_EQ(s.error, "");
  double worst = 0;
  int driving = 0;
  for (const Exchange& e : s.exchanges) {
    ASSERT_TRUE(e.answered);
    if (!e.whileDriving()) continue;
    ++driving;
    worst = std::max(worst, e.roundTripMs());
  }
  EXPECT_GE(driving, 20) << "too few exchanges while the robot moved";
  EXPECT_LE(worst, 100.0) << "slowest round trip while driving, emulated ms";
}

}  // namespace
}  // namespace nxtmap::emu::lego
