// The emulator's BC4 model on its own, driven the way the ARM drives it (RESET, ARM7_CMD, UART bytes):
// the mode follows ARM7_CMD (the module's messages only in command mode, the ARM's bytes in data mode
// are never taken for commands), a lost link's bytes never reach the next PC, and the PC's input is
// bounded with the rest left to the transport.
#include "host/emu/BlueCore.hpp"
#include "host/emu/LinkEndpoint.hpp"
#include "host/emu/Pioa.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace nxtmap::emu::test {
namespace {

constexpr uint32_t kReset = 1u << BlueCore::kResetPin, kArmCmd = 1u << BlueCore::kArmCmdPin;

// A PC side that also records how many bytes each send() carried (one radio packet each).
struct PacketLink : MemoryLink {
  std::vector<size_t> packets;
  void send(const uint8_t* d, size_t n) override {
    packets.push_back(n);
    MemoryLink::send(d, n);
  }
};

// The ARM's side of the module: PIO pins, UART bytes, and time in milliseconds.
struct ArmSide {
  Clock clock;
  Pioa pio{clock};
  PacketLink pc;
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
  // Stream bytes as the USART shifts them out: one every byteCycles, the module's events on time.
  void sendAtRate(size_t n, uint64_t byteCycles) {
    for (size_t i = 0; i < n; ++i) {
      const uint64_t at = clock.now + byteCycles;
      while (bc4.nextEventAt() <= at) {
        clock.now = bc4.nextEventAt();
        bc4.advanceTo(clock.now);
      }
      clock.now = at;
      bc4.fromArm(static_cast<uint8_t>(i));
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

// LEGO's firmware 1.29 accepts a PC as c_comm.c's UPD_CONNECTREQ does: ACCEPT_CONNECTION, LOOKUP_NAME of the
// caller, ADD_DEVICE, then OPEN_STREAM. Rows: the command, the module's answer (codes, then the payload of
// the first), and whether a stream opens after OPEN_STREAM.
TEST(BlueCoreModel, LegosConnectSequenceLooksUpThePcAndAddsItBeforeTheStreamOpens) {
  const std::vector<uint8_t> caller{0x00, 0x16, 0x53, 0x0E, 0x4D, 0x5A, 0x00};  // as REQUEST_CONNECTION gives it
  std::vector<uint8_t> lookUp{0x04};
  lookUp.insert(lookUp.end(), caller.begin(), caller.end());
  std::vector<uint8_t> other = lookUp;
  other[6] = 0x77;
  std::vector<uint8_t> addDevice{0x05};
  addDevice.insert(addDevice.end(), caller.begin(), caller.end());
  addDevice.resize(addDevice.size() + 16 + 4, 0);
  ArmSide arm;
  arm.command({0x03});
  arm.messages();
  arm.command(lookUp);
  EXPECT_EQ(arm.messages(), std::vector<uint8_t>{0x12}) << "no PC connected: LOOKUP_NAME_FAILURE";
  arm.pc.pcConnected = true;
  arm.advanceMs(2);
  EXPECT_EQ(arm.messages(), std::vector<uint8_t>{0x16});
  arm.command({0x09, 1});
  EXPECT_EQ(arm.messages(), std::vector<uint8_t>{0x13});
  arm.command(other);
  EXPECT_EQ(arm.messages(), std::vector<uint8_t>{0x12}) << "another address: LOOKUP_NAME_FAILURE";
  arm.command(lookUp);
  const std::vector<uint8_t> r = arm.received();
  ASSERT_EQ(r.size(), 1u + 1 + 7 + 16 + 4 + 2);  // [len][0x11][address][name][class][checksum]
  EXPECT_EQ(r[1], 0x11);
  EXPECT_EQ(std::vector<uint8_t>(r.begin() + 2, r.begin() + 9), caller);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(&r[9])), "nxtmap PC");
  arm.command(addDevice);
  const std::vector<uint8_t> list = arm.received();
  ASSERT_EQ(list.size(), 5u);
  EXPECT_EQ(list[1], 0x17);  // LIST_RESULT
  EXPECT_EQ(list[2], 0x50);  // LR_SUCCESS
  EXPECT_TRUE(arm.bc4.unknownCommands().empty());
  arm.command({0x0B, 1});
  arm.armCmd(true);
  EXPECT_TRUE(arm.bc4.streaming());
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

// The ARM's stream bytes reach the PC in bursts, one per transmit buffer (a quiet UART ends it), never one
// send per byte: rows of buffers (sizes, the pause after each) and the packets the PC gets.
TEST(BlueCoreModel, StreamBytesReachThePcInOneBurstPerTransmitBuffer) {
  constexpr uint64_t kByte = 1043;  // 10 bits at 460800 baud, in MCK cycles
  struct Row {
    std::vector<size_t> buffers;
    uint64_t pauseCycles;
    std::vector<size_t> packets;
  };
  const Row rows[] = {
      {{7}, cyclesFromMs(1), {7}},                                // one reply telegram
      {{7, 40, 3}, cyclesFromMs(1), {7, 40, 3}},                  // three buffers, the main loop between them
      {{7, 40}, 2 * kByte, {47}},                                 // the next buffer started within the gap
      {{3000}, cyclesFromMs(1), {1024, 1024, 952}},               // a burst holds at most kMaxBurstBytes
      {{1, 1, 1}, BlueCore::kBurstGapCycles + kByte, {1, 1, 1}},  // single bytes a gap apart
  };
  for (const Row& r : rows) {
    ArmSide arm;
    arm.toStream();
    for (size_t n : r.buffers) {
      arm.sendAtRate(n, kByte);
      const uint64_t until = arm.clock.now + r.pauseCycles;
      while (arm.bc4.nextEventAt() <= until) {
        arm.clock.now = arm.bc4.nextEventAt();
        arm.bc4.advanceTo(arm.clock.now);
      }
      arm.clock.now = until;
    }
    arm.advanceMs(1);
    EXPECT_EQ(arm.pc.packets, r.packets) << "first buffer " << r.buffers[0] << " bytes";
    size_t total = 0;
    for (size_t n : r.buffers) total += n;
    EXPECT_EQ(arm.pc.fromBrick.size(), total);
    EXPECT_EQ(arm.bc4.bytesToPc(), total);
  }
}

}  // namespace
}  // namespace nxtmap::emu::test
