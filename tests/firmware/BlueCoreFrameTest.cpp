#include <gtest/gtest.h>

#include <vector>

#include "firmware/drivers/BlueCoreFrame.hpp"

namespace nxtmap::fw {
namespace {

std::vector<uint8_t> encode(uint8_t code, std::vector<uint8_t> payload) {
  uint8_t out[kBcMaxPayload + 4];
  const uint8_t n = encodeBcCommand(code, payload.data(), static_cast<uint8_t>(payload.size()), out);
  return std::vector<uint8_t>(out, out + n);
}

TEST(BlueCoreFrame, CommandsToTheModuleLeaveTheLengthOutOfTheChecksum) {
  // Known frames (START_HEART, GET_VERSION, SET_DISCOVERABLE(1), OPEN_PORT).
  EXPECT_EQ(encode(0x0C, {}), (std::vector<uint8_t>{0x03, 0x0C, 0xFF, 0xF4}));
  EXPECT_EQ(encode(0x2F, {}), (std::vector<uint8_t>{0x03, 0x2F, 0xFF, 0xD1}));
  EXPECT_EQ(encode(0x1C, {0x01}), (std::vector<uint8_t>{0x04, 0x1C, 0x01, 0xFF, 0xE3}));
  EXPECT_EQ(encode(bc::kOpenPort, {}), (std::vector<uint8_t>{0x03, 0x03, 0xFF, 0xFD}));
}

TEST(BlueCoreFrame, TooLongPayloadIsRefused) {
  uint8_t payload[kBcMaxPayload + 1] = {};
  uint8_t out[kBcMaxPayload + 8];
  EXPECT_EQ(encodeBcCommand(0x05, payload, kBcMaxPayload + 1, out), 0);
}

TEST(BlueCoreFrame, MessagesFromTheModuleIncludeTheLengthInTheChecksum) {
  BcParser p;
  const uint8_t resetIndication[] = {0x03, 0x14, 0xFF, 0xE9};
  for (size_t i = 0; i < 3; ++i) EXPECT_FALSE(p.push(resetIndication[i]));
  EXPECT_TRUE(p.push(resetIndication[3]));
  EXPECT_EQ(p.code(), bc::kResetIndication);
  EXPECT_EQ(p.payloadLength(), 0);
  // CONNECT_RESULT(status 1, handle 5): sum = 05 13 01 05 = 0x1E -> 0xFFE2.
  const uint8_t connect[] = {0x05, 0x13, 0x01, 0x05, 0xFF, 0xE2};
  bool done = false;
  for (uint8_t b : connect) done = p.push(b);
  ASSERT_TRUE(done);
  EXPECT_EQ(p.code(), bc::kConnectResult);
  ASSERT_EQ(p.payloadLength(), 2);
  EXPECT_EQ(p.payload()[0], 1);
  EXPECT_EQ(p.payload()[1], 5);
}

TEST(BlueCoreFrame, AMessageWithTheOutgoingChecksumRuleIsRejected) {
  BcParser p;
  const uint8_t wrongRule[] = {0x03, 0x14, 0xFF, 0xEC};  // length left out of the sum
  bool done = false;
  for (uint8_t b : wrongRule) done = p.push(b);
  EXPECT_FALSE(done);
  EXPECT_EQ(p.badMessages(), 1u);
}

TEST(BlueCoreFrame, ImplausibleLengthBytesAreSkipped) {
  BcParser p;
  const uint8_t noise[] = {0x00, 0x01, 0xFE, 0x03, 0x14, 0xFF, 0xE9};
  bool done = false;
  for (uint8_t b : noise) done = p.push(b);
  EXPECT_TRUE(done);
  EXPECT_EQ(p.code(), bc::kResetIndication);
  EXPECT_EQ(p.badMessages(), 3u);
}

}  // namespace
}  // namespace nxtmap::fw
