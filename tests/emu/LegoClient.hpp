// LegoClient: the PC side of LEGO's direct and system commands over Bluetooth, as a PC tool speaks them,
// written from the tables of the LEGO Mindstorms NXT Bluetooth Developer Kit (Appendix 1: system commands,
// Appendix 2: direct commands) and nothing of common/protocol, so a test with it checks our brick against
// LEGO's protocol and not against our own encoder. A telegram is [type][opcode][arguments...]; on the
// wire each is preceded by its length, two bytes little-endian. Replies are [0x02][opcode][status][...].
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace nxtmap::emu::lego {

using Bytes = std::vector<uint8_t>;

// Telegram types (byte 0).
constexpr uint8_t kDirect = 0x00, kSystem = 0x01, kReply = 0x02, kDirectNoReply = 0x80, kSystemNoReply = 0x81;

// Opcodes (byte 1): direct commands 0x00..0x13, system commands 0x80 and up.
enum Opcode : uint8_t {
  kStartProgram = 0x00,
  kStopProgram = 0x01,
  kPlayTone = 0x03,
  kSetOutputState = 0x04,
  kSetInputMode = 0x05,
  kGetOutputState = 0x06,
  kGetInputValues = 0x07,
  kMessageWrite = 0x09,
  kResetMotorPosition = 0x0A,
  kGetBatteryLevel = 0x0B,
  kStopSoundPlayback = 0x0C,
  kKeepAlive = 0x0D,
  kLsGetStatus = 0x0E,
  kGetCurrentProgramName = 0x11,
  kMessageRead = 0x13,
  kGetFirmwareVersion = 0x88,
  kSetBrickName = 0x98,
  kGetDeviceInfo = 0x9B,
};

// Status codes (reply byte 2) a test names; the rest are in the kit's table.
constexpr uint8_t kSuccess = 0x00, kMailboxEmpty = 0x40, kUnknownOpcode = 0xBE, kOutOfRange = 0xC0,
                  kNoActiveProgram = 0xEC, kIllegalMailbox = 0xEE, kBadArguments = 0xFF;

// Requests, as telegrams without the length; `reply` false sends type 0x80 (no reply wanted).
Bytes getBatteryLevel(bool reply = true);
Bytes keepAlive(bool reply = true);
Bytes messageWrite(uint8_t inbox, const std::string& text, bool reply = true);  // text + NUL, 1..59 bytes
Bytes messageRead(uint8_t remoteInbox, uint8_t localInbox, bool remove);
Bytes getOutputState(uint8_t port);  // port 0..2 = A..C
// SET_OUTPUT_STATE: power -100..100, mode bits (MOTORON 1, BRAKE 2, REGULATED 4), regulation mode (IDLE 0,
// MOTOR_SPEED 1, MOTOR_SYNC 2), turn ratio -100..100, run state (IDLE 0, RAMPUP 0x10, RUNNING 0x20,
// RAMPDOWN 0x40), tacho limit in degrees (0 = run forever).
constexpr uint8_t kMotorOn = 0x01, kBrake = 0x02, kRegulated = 0x04, kRegulationSpeed = 0x01, kRunning = 0x20;
Bytes setOutputState(uint8_t port, int8_t power, uint8_t mode, uint8_t regulation, int8_t turnRatio, uint8_t runState,
                     uint32_t tachoLimit, bool reply = true);
Bytes getInputValues(uint8_t port);  // port 0..3 = 1..4
Bytes playTone(uint16_t hz, uint16_t ms, bool reply = true);
Bytes setInputMode(uint8_t port, uint8_t type, uint8_t mode, bool reply = true);
Bytes stopProgram();
Bytes getCurrentProgramName();
Bytes resetMotorPosition(uint8_t port, bool relative);
Bytes lsGetStatus(uint8_t port);
Bytes getFirmwareVersion();
Bytes getDeviceInfo();

// The request's reply telegram size from the kit's tables (type and opcode included); 0 when the
// request asks for no reply.
size_t replySize(const Bytes& request);

// The frame on the wire: [size LE16] + telegram.
Bytes framed(const Bytes& telegram);

// A reply telegram's fields (little-endian), each read at its byte offset in the telegram.
struct Reply {
  Bytes bytes;
  uint8_t type() const { return bytes.size() > 0 ? bytes[0] : 0; }
  uint8_t opcode() const { return bytes.size() > 1 ? bytes[1] : 0; }
  uint8_t status() const { return bytes.size() > 2 ? bytes[2] : 0xFF; }
  uint8_t u8(size_t at) const { return at < bytes.size() ? bytes[at] : 0; }
  uint16_t u16(size_t at) const { return static_cast<uint16_t>(u8(at) | (u8(at + 1) << 8)); }
  uint32_t u32(size_t at) const { return u16(at) | (static_cast<uint32_t>(u16(at + 2)) << 16); }
  std::string text(size_t at, size_t n) const;  // up to the first NUL within n bytes
};

// Cuts a byte stream into telegrams by their length prefix, whatever the chunks it arrives in.
class TelegramSplitter {
 public:
  void push(const uint8_t* data, size_t n) { buffer_.insert(buffer_.end(), data, data + n); }
  bool pop(Bytes& telegram);  // the next whole telegram, false if none yet

 private:
  std::deque<uint8_t> buffer_;
};

}  // namespace nxtmap::emu::lego
