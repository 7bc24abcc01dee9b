// The emulator's BC4 model on its own, driven the way the ARM drives it (RESET, ARM7_CMD, UART bytes):
// the mode follows ARM7_CMD (the module's messages only in command mode, the ARM's bytes in data mode
// are never taken for commands), a lost link's bytes never reach the next PC, and the PC's input is
// bounded with the rest left to the transport.
#include "host/emu/BlueCore.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/emu/Pioa.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kReset = 1u << BlueCore::kResetPin, kArmCmd = 1u << BlueCore::kArmCmdPin;

// The ARM's side of the module: PIO pins, UART bytes, and time in milliseconds.
struct ArmSide {
  Clock clock;
  Pioa pio{clock};
  MemoryLink pc;
  BlueCore bc4{clock, pio, &pc};

  ArmSide() {
    pio.write(0x00, kReset | kArmCmd);  // PER
    pio.write(0x34, kReset | kArmCmd);  // CODR: in reset, command mode
    pio.write(0x10, kReset | kArmCmd);  // OER
    pc.pcConnected = false;
    advanceMs(1);
    pio.write(0x30, kReset);  // SODR: RESET released
    advanceMs(60);
    EXPECT_EQ(messages(), std::vector<uint8_t>{0x14});  // RESET_INDICATION
  }
  void advanceMs(uint32_t ms) {
    for (uint32_t i = 0; i < ms; ++i) {
      clock.now += cyclesFromMs(1);
      bc4.advanceTo(clock.now);
    }
  }
  void armCmd(bool high) { pio.write(high ? 0x30 : 0x34, kArmCmd); }
  // A command frame to the module: [len][cmd][payload][checksum over cmd + payload, big-endian].
  void command(std::vector<uint8_t> cmdAndPayload) {
    unsigned sum = 0;
    for (uint8_t b : cmdAndPayload) sum += b;
    const unsigned cs = (0x10000u - sum) & 0xFFFF;
    send({static_cast<uint8_t>(cmdAndPayload.size() + 2)});
    send(cmdAndPayload);
    send({static_cast<uint8_t>(cs >> 8), static_cast<uint8_t>(cs)});
  }
  void send(const std::vector<uint8_t>& bytes) {
    for (uint8_t b : bytes) bc4.fromArm(b);
  }
  std::vector<uint8_t> received() {
    std::vector<uint8_t> out;
    while (bc4.hasByteForArm()) out.push_back(bc4.takeByteForArm());
    return out;
  }
  // The codes of the module's messages waiting for the ARM.
  std::vector<uint8_t> messages() {
    const std::vector<uint8_t> bytes = received();
    std::vector<uint8_t> codes;
    for (size_t i = 0; i + 1 < bytes.size(); i += bytes[i] + 1u) codes.push_back(bytes[i + 1]);
    return codes;
  }
  // Port open, a PC dialled in and accepted, stream open, ARM7_CMD high.
  void toStream() {
    command({0x03});
    EXPECT_EQ(messages(), std::vector<uint8_t>{0x1B});
    pc.pcConnected = true;
    advanceMs(2);
    EXPECT_EQ(messages(), std::vector<uint8_t>{0x16});  // REQUEST_CONNECTION
    command({0x09, 1});
    EXPECT_EQ(messages(), std::vector<uint8_t>{0x13});
    command({0x0B, 1});
    armCmd(true);
    EXPECT_TRUE(bc4.streaming());
  }
};

TEST(BlueCoreModel, TheHangUpMessageWaitsForCommandModeAndStreamBytesAreNeverCommands) {
  ArmSide arm;
  arm.toStream();
  const uint64_t commands = arm.bc4.commandsSeen();
  arm.pc.pcConnected = false;  // the PC hangs up
  arm.advanceMs(2);
  EXPECT_FALSE(arm.bc4.cmdSignal());
  EXPECT_FALSE(arm.bc4.hasByteForArm()) << "a message while the ARM still reads the stream";
  arm.send({0x40, 0x00, 0x12, 0x34});  // the ARM's last stream bytes, sent before it saw the CMD line drop
  arm.armCmd(false);
  EXPECT_EQ(arm.messages(), std::vector<uint8_t>{0x1A});  // CLOSE_CONNECTION_RESULT
  arm.command({0x03});
  EXPECT_EQ(arm.messages(), std::vector<uint8_t>{0x1B}) << "OPEN_PORT answered";
  EXPECT_EQ(arm.bc4.commandsSeen(), commands + 1);
  EXPECT_EQ(arm.bc4.badFrames(), 0u);
  EXPECT_TRUE(arm.pc.fromBrick.empty());
}

TEST(BlueCoreModel, TheBytesOfALostLinkNeverReachTheNextPc) {
  ArmSide arm;
  arm.toStream();
  arm.pc.toBrick = {1, 2, 3};
  arm.advanceMs(2);
  ASSERT_EQ(arm.bc4.pcBuffered(), 3u);
  arm.pc.pcConnected = false;
  arm.advanceMs(2);
  EXPECT_EQ(arm.bc4.pcBuffered(), 0u);
  arm.armCmd(false);
  arm.received();
  arm.toStream();  // the next PC
  EXPECT_TRUE(arm.received().empty());
  arm.pc.toBrick = {9};
  arm.advanceMs(2);
  EXPECT_EQ(arm.received(), std::vector<uint8_t>{9});
}

TEST(BlueCoreModel, ThePcsInputIsBoundedAndTheRestWaitsInTheTransport) {
  ArmSide arm;
  arm.toStream();
  arm.pc.toBrick.assign(100000, 0x55);
  for (int ms = 0; ms < 5; ++ms) {
    arm.advanceMs(1);
    EXPECT_LE(arm.bc4.pcBuffered(), BlueCore::kPcInputBytes);
  }
  EXPECT_EQ(arm.bc4.pcBuffered(), BlueCore::kPcInputBytes);
  EXPECT_EQ(arm.pc.toBrick.size(), 100000 - BlueCore::kPcInputBytes);
  size_t delivered = 0;
  while (arm.pc.toBrick.size() > 0 && delivered < 200000) {  // the ARM reads; more comes in
    delivered += arm.received().size();
    arm.advanceMs(1);
    EXPECT_LE(arm.bc4.pcBuffered(), BlueCore::kPcInputBytes);
  }
  delivered += arm.received().size();
  EXPECT_EQ(delivered, 100000u);
}

}  // namespace
}  // namespace nxtmap::emu::test
