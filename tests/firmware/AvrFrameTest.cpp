#include <gtest/gtest.h>

#include <string>

#include "firmware/drivers/AvrFrame.hpp"

namespace nxtmap::fw {
namespace {

uint8_t sum(const uint8_t* b, int n) {
  uint8_t s = 0;
  for (int i = 0; i < n; ++i) s = static_cast<uint8_t>(s + b[i]);
  return s;
}

TEST(AvrFrame, HandshakeIsTheExactCopyrightString) {
  uint8_t hs[kAvrHandshakeBytes];
  packAvrHandshake(hs);
  EXPECT_EQ(hs[0], 0xCC);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(hs + 1), 46), "Let's samba nxt arm in arm, (c)LEGO System A/S");
  EXPECT_EQ(kAvrHandshakeBytes, 47);
}

TEST(AvrFrame, CommandLayoutAndChecksum) {
  AvrCommand c;
  c.pwm[0] = 75;
  c.pwm[1] = -40;
  c.brakeMask = 0x04;
  c.inputPower = constant9v(0) | constant9v(3);
  uint8_t f[kAvrTxBytes];
  packAvrCommand(c, f);
  EXPECT_EQ(f[0], 0);  // power: normal
  EXPECT_EQ(f[1], 8);  // 8 kHz PWM
  EXPECT_EQ(f[2], 75);
  EXPECT_EQ(f[3], 0xD8);  // -40
  EXPECT_EQ(f[4], 0);
  EXPECT_EQ(f[5], 0);
  EXPECT_EQ(f[6], 0x04);
  EXPECT_EQ(f[7], 0x90);  // constant 9 V on ports 1 and 4
  EXPECT_EQ(sum(f, 9), 0xFF);
  EXPECT_EQ(f[8], static_cast<uint8_t>(~sum(f, 8)));
}

TEST(AvrFrame, PowerIsClampedToPlusMinus100) {
  AvrCommand c;
  c.pwm[0] = 127;
  c.pwm[1] = -128;
  uint8_t f[kAvrTxBytes];
  packAvrCommand(c, f);
  EXPECT_EQ(static_cast<int8_t>(f[2]), 100);
  EXPECT_EQ(static_cast<int8_t>(f[3]), -100);
  EXPECT_EQ(sum(f, 9), 0xFF);
}

TEST(AvrFrame, StatusDecodesLittleEndianFieldsWithAGoodChecksum) {
  uint8_t f[kAvrRxBytes] = {0x10, 0x02, 0xFF, 0x03, 0, 0, 1, 0, 0x20, 0x03, 0x0A, 0x82, 0};
  f[12] = static_cast<uint8_t>(0xFF - sum(f, 12));
  AvrStatus s;
  ASSERT_TRUE(parseAvrStatus(f, s));
  EXPECT_EQ(s.analog[0], 0x210);
  EXPECT_EQ(s.analog[1], 0x3FF);
  EXPECT_EQ(s.analog[3], 1);
  EXPECT_EQ(s.buttonsRaw, 0x320);
  EXPECT_EQ(s.batteryRaw, 0x820A);
  EXPECT_EQ(batteryMillivolts(s.batteryRaw), (0x20Au * 13848u) / 1000u);  // bit 15 (pack) ignored
}

TEST(AvrFrame, StatusWithABadChecksumIsRejectedAndChangesNothing) {
  uint8_t f[kAvrRxBytes] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0};
  f[12] = static_cast<uint8_t>(0xFF - sum(f, 12) + 1);
  AvrStatus s;
  s.buttonsRaw = 777;
  EXPECT_FALSE(parseAvrStatus(f, s));
  EXPECT_EQ(s.buttonsRaw, 777);
}

TEST(AvrFrame, ButtonLadder) {
  EXPECT_EQ(decodeButton(0), Button::None);
  EXPECT_EQ(decodeButton(100), Button::Left);
  EXPECT_EQ(decodeButton(400), Button::Right);
  EXPECT_EQ(decodeButton(900), Button::Exit);
  EXPECT_EQ(decodeButton(0x7FF + 10), Button::Enter);
}

}  // namespace
}  // namespace nxtmap::fw
