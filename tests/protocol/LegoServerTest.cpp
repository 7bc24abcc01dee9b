// LEGO's direct and system commands as the brick answers them, byte for byte as LEGO's Bluetooth
// developer kit lays out commands and replies (written here from its tables, not by our encoders).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/protocol/LegoCommands.hpp"
#include "common/protocol/LegoServer.hpp"
#include "tests/protocol/FakeLegoBrick.hpp"

namespace nxtmap::protocol {
namespace {

using test::Bytes;
using test::cat;
using test::FakeBrick;
using test::idle;
using test::telegramOf;

// Every reply the server gives for `commands` sent back to back, as telegrams.
std::vector<Bytes> answers(LegoServer& s, LegoBrick& brick, const std::vector<Bytes>& commands,
                           const LegoContext& ctx) {
  for (const Bytes& c : commands) s.take(telegramOf(c));
  std::vector<Bytes> out;
  Frame f;
  while (s.next(ctx, brick, f)) {
    EXPECT_EQ(f.bytes[0] | (f.bytes[1] << 8), f.size - 2);
    out.emplace_back(f.bytes + 2, f.bytes + f.size);
  }
  return out;
}

Bytes zeros(size_t n) { return Bytes(n, 0); }

TEST(LegoServer, AnswersEachServedCommandWithLegosLayout) {
  struct Case {
    const char* what;
    Bytes command;
    Bytes reply;  // empty: no reply
  };
  const Bytes name = cat({'n', 'x', 't', 'm', 'a', 'p'}, zeros(9));
  const Case cases[] = {
      {"battery", {0x00, 0x0B}, {0x02, 0x0B, 0x00, 0x2C, 0x1F}},                 // 7980 mV
      {"keep alive", {0x00, 0x0D}, {0x02, 0x0D, 0x00, 0x60, 0xEA, 0x00, 0x00}},  // 60000 ms
      {"battery, no reply", {0x80, 0x0B}, {}},
      {"play tone 440 Hz 200 ms", {0x00, 0x03, 0xB8, 0x01, 0xC8, 0x00}, {0x02, 0x03, 0x00}},
      {"stop sound", {0x00, 0x0C}, {0x02, 0x0C, 0x00}},
      {"firmware version", {0x01, 0x88}, {0x02, 0x88, 0x00, 124, 1, 4, 0}},
      {"device info",
       {0x01, 0x9B},
       cat(cat({0x02, 0x9B, 0x00}, name), {0x00, 0x16, 0x53, 0x0A, 0x0B, 0x0C, 0, 0, 0, 0, 0, 0x00, 0x00, 0x03, 0x00})},
      {"output B", {0x00, 0x06, 0x01}, {0x02, 0x06, 0x00, 0x01, 0xF6, 0x01, 0x00, 0x00, 0x20, 0x68, 0x01, 0,   0,
                                        0xE9, 0x03, 0,    0,    0xFE, 0xFF, 0xFF, 0xFF, 0x04, 0x03, 0x02, 0x01}},
      {"output D does not exist", {0x00, 0x06, 0x03}, cat({0x02, 0x06, 0xC0}, zeros(22))},
      {"input 2 (ultrasonic, 41 cm)",
       {0x00, 0x07, 0x01},
       {0x02, 0x07, 0x00, 0x01, 1, 0, 0x0B, 0x00, 0, 0, 0, 0, 41, 0, 41, 0}},
      {"input 4, no reading yet", {0x00, 0x07, 0x03}, {0x02, 0x07, 0x00, 0x03, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}},
      {"input 5 does not exist", {0x00, 0x07, 0x04}, cat({0x02, 0x07, 0xC0}, zeros(13))},
      {"reset position A relative", {0x00, 0x0A, 0x00, 0x01}, {0x02, 0x0A, 0x00}},
      {"reset position D", {0x00, 0x0A, 0x03, 0x00}, {0x02, 0x0A, 0xC0}},
      {"set output C", {0x00, 0x04, 0x02, 75, 0x01, 0x00, 0x00, 0x20, 0x68, 0x01, 0x00, 0x00}, {0x02, 0x04, 0x00}},
      {"set output, power 101", {0x00, 0x04, 0x02, 101, 0x01, 0x00, 0x00, 0x20, 0, 0, 0, 0}, {0x02, 0x04, 0xC0}},
      {"set brick name", cat({0x01, 0x98, 'r', 'o', 'v', 'e', 'r'}, zeros(10)), {0x02, 0x98, 0x00}},
      {"write box 3", {0x00, 0x09, 0x03, 0x03, 'h', 'i', 0x00}, {0x02, 0x09, 0x00}},
      {"write box 19", {0x00, 0x09, 19, 0x02, 'y', 0x00}, {0x02, 0x09, 0x00}},
      {"write box 20", {0x00, 0x09, 20, 0x02, 'y', 0x00}, {0x02, 0x09, 0xEE}},
      {"read box 19", {0x00, 0x13, 19, 7, 1}, cat({0x02, 0x13, 0x00, 7, 2, 'y', 0}, zeros(57))},
      {"read empty box 19", {0x00, 0x13, 19, 7, 1}, cat({0x02, 0x13, 0x40, 7, 0}, zeros(59))},
      {"read box 20", {0x00, 0x13, 20, 0, 0}, cat({0x02, 0x13, 0xEE, 0, 0}, zeros(59))},
  };
  LegoServer s;
  FakeBrick brick;
  for (const Case& c : cases) {
    const std::vector<Bytes> got = answers(s, brick, {c.command}, idle());
    if (c.reply.empty()) {
      EXPECT_TRUE(got.empty()) << c.what;
    } else {
      ASSERT_EQ(got.size(), 1u) << c.what;
      EXPECT_EQ(got[0], c.reply) << c.what;
    }
  }
  EXPECT_STREQ(s.name(), "rover");
  ASSERT_EQ(brick.tones.size(), 1u);
  EXPECT_EQ(brick.tones[0], std::make_pair(uint16_t{440}, uint16_t{200}));
  EXPECT_EQ(brick.stops, 1);
  ASSERT_EQ(brick.set.size(), 1u);
  EXPECT_EQ(brick.set[0].port, 2);
  EXPECT_EQ(brick.set[0].power, 75);
  EXPECT_EQ(brick.set[0].runState, kLegoRunRunning);
  EXPECT_EQ(brick.set[0].tachoLimit, 360u);
  EXPECT_EQ(brick.resets, std::vector<int>{1});
}

TEST(LegoServer, UnknownCommandsGetTheUnknownStatusOrNothing) {
  struct Case {
    const char* what;
    Bytes command;
    Bytes reply;  // empty: no reply
  };
  const Case cases[] = {
      {"stop program", {0x00, 0x01}, {0x02, 0x01, 0xBE}},
      {"current program name", {0x00, 0x11}, {0x02, 0x11, 0xBE}},
      {"LS get status", {0x00, 0x0E, 0x00}, {0x02, 0x0E, 0xBE}},
      {"set input mode, reply wanted", {0x00, 0x05, 0x00, 0x0B, 0x00}, {0x02, 0x05, 0xBE}},
      {"set input mode, no reply", {0x80, 0x05, 0x00, 0x0B, 0x00}, {}},
      {"file open read", cat({0x01, 0x80}, zeros(20)), {0x02, 0x80, 0xBE}},
      {"boot, no reply", cat({0x81, 0x97}, zeros(19)), {}},
      {"battery with a stray byte", {0x00, 0x0B, 0x00}, {0x02, 0x0B, 0xBF, 0x00, 0x00}},
      {"message write not NUL-terminated", {0x00, 0x09, 1, 3, 'a', 'b', 'c'}, {0x02, 0x09, 0xBF}},
      {"a reply (the brick asked nothing)", {0x02, 0x0B, 0x00, 0x10, 0x1F}, {}},
  };
  LegoServer s;
  FakeBrick brick;
  for (const Case& c : cases) {
    const std::vector<Bytes> got = answers(s, brick, {c.command}, idle());
    if (c.reply.empty()) {
      EXPECT_TRUE(got.empty()) << c.what;
    } else {
      ASSERT_EQ(got.size(), 1u) << c.what;
      EXPECT_EQ(got[0], c.reply) << c.what;
    }
  }
  EXPECT_FALSE(s.pending());
}

TEST(LegoServer, MotorCommandsAreRefusedWhileTheRobotMoves) {
  LegoServer s;
  FakeBrick brick;
  LegoContext busy = idle();
  busy.motorsBusy = true;
  const std::vector<Bytes> got = answers(s, brick,
                                         {{0x00, 0x04, 0xFF, 50, 0x01, 0, 0, 0x20, 0, 0, 0, 0},
                                          {0x00, 0x0A, 0x00, 0x00},
                                          {0x80, 0x04, 0x00, 50, 0x01, 0, 0, 0x20, 0, 0, 0, 0},
                                          {0x00, 0x06, 0x00}},
                                         busy);
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0], (Bytes{0x02, 0x04, 0xBD}));
  EXPECT_EQ(got[1], (Bytes{0x02, 0x0A, 0xBD}));
  EXPECT_EQ(got[2][2], kLegoOk);  // reading the tachometers is always allowed
  EXPECT_TRUE(brick.set.empty());
  EXPECT_TRUE(brick.resets.empty());
  // Idle: all three outputs, one call each.
  const std::vector<Bytes> idleGot = answers(s, brick, {{0x00, 0x04, 0xFF, 50, 0x01, 0, 0, 0x20, 0, 0, 0, 0}}, idle());
  EXPECT_EQ(idleGot[0], (Bytes{0x02, 0x04, 0x00}));
  ASSERT_EQ(brick.set.size(), 3u);
  EXPECT_EQ(brick.set[2].port, 2);
}

TEST(LegoTelegrams, OnlyExactLayoutsAreKnownToTheByte) {
  struct Case {
    Bytes t;
    bool known;
  };
  const Case cases[] = {
      {{0x00, 0x0B}, true},
      {{0x80, 0x03, 0, 0, 0, 0}, true},
      {{0x00, 0x0B, 0x00}, false},                 // a stray byte
      {{0x00, 0x09, 1, 3, 'a', 'b', 'c'}, false},  // not NUL-terminated
      {{0x00, 0x09, 1, 60, 0}, false},             // size beyond 59 / mismatch
      {{0x00, 0x05, 0, 0x0B, 0}, false},           // SET_INPUT_MODE: not served
      {{0x01, 0x9B}, true},
      {{0x02, 0x0B, 0x00, 0x10, 0x1F}, true},
      {{0x02, 0x05, 0xBE}, true},
      {{0x02, 0x0B, 0x00}, true},  // a status reply
      {{0x4E, 0x02}, false},
  };
  for (const Case& c : cases) EXPECT_EQ(legoTelegramKnown(c.t.data(), c.t.size()), c.known) << int(c.t[1]);
}

}  // namespace
}  // namespace nxtmap::protocol
