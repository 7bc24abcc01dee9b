// The AVR model as the ATmega48's program treats a TWI write (LEGO ATmega48/Source: the copyright string
// after 0xCC arms it; any other frame whose first 9 bytes sum to 0xFF is obeyed, bytes after them ignored)
// and what a read returns (4 A/D values, buttons, battery, checksum).
#include "host/emu/AvrModel.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace nxtmap::emu::test {
namespace {

const std::string kCopyright = "Let's samba nxt arm in arm, (c)LEGO System A/S";

std::vector<uint8_t> handshake(const std::string& text = kCopyright) {
  std::vector<uint8_t> f(1 + text.size(), 0xCC);
  for (size_t i = 0; i < text.size(); ++i) f[1 + i] = static_cast<uint8_t>(text[i]);
  return f;
}

// power, frequency, four motor powers, brake mask, input power, then the checksum making the sum 0xFF.
std::vector<uint8_t> command(int a, int b, int c, uint8_t brake, uint8_t input, uint8_t first = 0) {
  std::vector<uint8_t> f{first, 8,    static_cast<uint8_t>(a), static_cast<uint8_t>(b), static_cast<uint8_t>(c), 0,
                         brake, input};
  unsigned sum = 0;
  for (uint8_t v : f) sum += v;
  f.push_back(static_cast<uint8_t>(0xFF - (sum & 0xFF)));
  return f;
}

std::vector<uint8_t> badSum(std::vector<uint8_t> f) {
  f.back() ^= 1;
  return f;
}

TEST(AvrModel, FramesAreObeyedOrCountedBadAsTheAtmegaProgramDoes) {
  struct Row {
    const char* what;
    std::vector<uint8_t> frame;
    bool handshake;
    uint64_t good, bad;
    int powerA;
  };
  auto withTail = [](std::vector<uint8_t> f) {
    f.push_back(0x00);
    f.push_back(0x42);
    return f;
  };
  auto shortFrame = command(10, 0, 0, 0, 0);
  shortFrame.resize(8);
  const Row rows[] = {
      {"the handshake", handshake(), true, 1, 0, 0},
      {"the handshake with trailing bytes", withTail(handshake()), true, 1, 0, 0},
      {"a wrong string", handshake("Let's samba nxt arm in arm, (c)LEGO System A/X"), false, 0, 1, 0},
      {"the string cut short", handshake("Let's samba nxt"), false, 0, 1, 0},
      {"a command with a good checksum, no handshake yet", command(40, 0, 0, 0, 0), false, 1, 0, 40},
      {"a command with trailing bytes", withTail(command(-30, 0, 0, 0, 0)), false, 1, 0, -30},
      {"a bad checksum", badSum(command(40, 0, 0, 0, 0)), false, 0, 1, 0},
      {"8 bytes: too short", shortFrame, false, 0, 1, 0},
      {"powers clamp to -100..100", command(120, 0, 0, 0, 0), false, 1, 0, 100},
      {"the address alone: nothing", {}, false, 0, 0, 0},
  };
  for (const Row& r : rows) {
    AvrModel avr;
    avr.receive(r.frame);
    EXPECT_EQ(avr.handshakeDone(), r.handshake) << r.what;
    EXPECT_EQ(avr.goodFrames(), r.good) << r.what;
    EXPECT_EQ(avr.badFrames(), r.bad) << r.what;
    EXPECT_EQ(avr.motorPower(0), r.powerA) << r.what;
  }
}

TEST(AvrModel, ACommandSetsMotorsBrakesAndSensorPower) {
  AvrModel avr;
  avr.receive(handshake());
  avr.receive(command(25, -128, 100, 0x5, 0x10 | 0x04));  // brake A and C; port 0 constant 9 V, port 2 pulsed
  EXPECT_EQ(avr.motorPower(0), 25);
  EXPECT_EQ(avr.motorPower(1), -100);
  EXPECT_EQ(avr.motorPower(2), 100);
  EXPECT_TRUE(avr.brake(0));
  EXPECT_FALSE(avr.brake(1));
  EXPECT_TRUE(avr.brake(2));
  EXPECT_TRUE(avr.sensorPowered(0));
  EXPECT_FALSE(avr.sensorPowered(1));
  EXPECT_TRUE(avr.sensorPowered(2));
  EXPECT_FALSE(avr.sensorPowered(3));
  avr.receive(badSum(command(0, 0, 0, 0, 0)));
  EXPECT_EQ(avr.motorPower(0), 25);  // a bad frame changes nothing
  EXPECT_FALSE(avr.powerDownRequested());
}

TEST(AvrModel, PowerDownFrames) {
  for (uint8_t first : {uint8_t{0x5A}}) {
    AvrModel avr;
    avr.receive(command(0, 0, 0, 0, 0, first));
    EXPECT_TRUE(avr.powerDownRequested());
  }
  AvrModel avr;
  std::vector<uint8_t> f{0xA5, 0x5A, 0, 0, 0, 0, 0, 0};
  unsigned sum = 0xA5 + 0x5A;
  f.push_back(static_cast<uint8_t>(0xFF - (sum & 0xFF)));
  avr.receive(f);
  EXPECT_TRUE(avr.powerDownRequested());
}

TEST(AvrModel, ReplyCarriesButtonsAndBatteryAndSumsTo0xFF) {
  struct Row {
    uint16_t buttons;
    int batteryMv;
    uint16_t batteryRaw;
  };
  const Row rows[] = {{0, 7800, 7800 * 1000 / 13848}, {0x7FF, 9000, 9000 * 1000 / 13848}, {0x0123, 0, 0}};
  for (const Row& r : rows) {
    AvrModel avr;
    avr.setButtons(r.buttons);
    avr.setBatteryMv(r.batteryMv);
    const auto reply = avr.reply();
    for (size_t p = 0; p < 4; ++p) EXPECT_EQ(reply[2 * p] | reply[2 * p + 1] << 8, 1023);  // pin 1 pulled up
    EXPECT_EQ(reply[8] | reply[9] << 8, r.buttons);
    EXPECT_EQ(reply[10] | reply[11] << 8, r.batteryRaw);
    unsigned sum = 0;
    for (uint8_t b : reply) sum += b;
    EXPECT_EQ(sum & 0xFF, 0xFFu);
  }
}

}  // namespace
}  // namespace nxtmap::emu::test
