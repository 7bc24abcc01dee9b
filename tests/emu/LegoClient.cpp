#include "LegoClient.hpp"

namespace nxtmap::emu::lego {
namespace {

Bytes command(uint8_t type, uint8_t opcode, bool reply, std::initializer_list<uint8_t> args = {}) {
  Bytes t;  // byte by byte: GCC 12 at -O3 takes vector::insert of a short list for an overflow
  t.reserve(2 + args.size() + 60);
  t.push_back(static_cast<uint8_t>(reply ? type : type | 0x80));
  t.push_back(opcode);
  for (uint8_t a : args) t.push_back(a);
  return t;
}

uint8_t lo(uint16_t v) { return static_cast<uint8_t>(v & 0xFF); }
uint8_t hi(uint16_t v) { return static_cast<uint8_t>(v >> 8); }

}  // namespace

Bytes getBatteryLevel(bool reply) { return command(kDirect, kGetBatteryLevel, reply); }
Bytes keepAlive(bool reply) { return command(kDirect, kKeepAlive, reply); }

Bytes messageWrite(uint8_t inbox, const std::string& text, bool reply) {
  Bytes t = command(kDirect, kMessageWrite, reply, {inbox, static_cast<uint8_t>(text.size() + 1)});
  for (char c : text) t.push_back(static_cast<uint8_t>(c));
  t.push_back(0);
  return t;
}

Bytes messageRead(uint8_t remoteInbox, uint8_t localInbox, bool remove) {
  return command(kDirect, kMessageRead, true, {remoteInbox, localInbox, static_cast<uint8_t>(remove ? 1 : 0)});
}

Bytes getOutputState(uint8_t port) { return command(kDirect, kGetOutputState, true, {port}); }
Bytes setOutputState(uint8_t port, int8_t power, uint8_t mode, uint8_t regulation, int8_t turnRatio, uint8_t runState,
                     uint32_t tachoLimit, bool reply) {
  return command(kDirect, kSetOutputState, reply,
                 {port, static_cast<uint8_t>(power), mode, regulation, static_cast<uint8_t>(turnRatio), runState,
                  static_cast<uint8_t>(tachoLimit), static_cast<uint8_t>(tachoLimit >> 8),
                  static_cast<uint8_t>(tachoLimit >> 16), static_cast<uint8_t>(tachoLimit >> 24)});
}
Bytes getInputValues(uint8_t port) { return command(kDirect, kGetInputValues, true, {port}); }
Bytes playTone(uint16_t hz, uint16_t ms, bool reply) {
  return command(kDirect, kPlayTone, reply, {lo(hz), hi(hz), lo(ms), hi(ms)});
}
Bytes setInputMode(uint8_t port, uint8_t type, uint8_t mode, bool reply) {
  return command(kDirect, kSetInputMode, reply, {port, type, mode});
}
Bytes stopProgram() { return command(kDirect, kStopProgram, true); }
Bytes getCurrentProgramName() { return command(kDirect, kGetCurrentProgramName, true); }
Bytes resetMotorPosition(uint8_t port, bool relative) {
  return command(kDirect, kResetMotorPosition, true, {port, static_cast<uint8_t>(relative ? 1 : 0)});
}
Bytes lsGetStatus(uint8_t port) { return command(kDirect, kLsGetStatus, true, {port}); }
Bytes getFirmwareVersion() { return command(kSystem, kGetFirmwareVersion, true); }
Bytes getDeviceInfo() { return command(kSystem, kGetDeviceInfo, true); }

size_t replySize(const Bytes& request) {
  if (request.size() < 2 || (request[0] & 0x80) != 0) return 0;
  switch (request[1]) {
    case kGetBatteryLevel: return 5;         // status, millivolts UWORD
    case kKeepAlive: return 7;               // status, sleep time limit ULONG (ms)
    case kMessageRead: return 64;            // status, local inbox, size, 59 bytes of message
    case kGetOutputState: return 25;         // status, port, power .. rotation count
    case kGetInputValues: return 16;         // status, port, valid .. calibrated value
    case kLsGetStatus: return 4;             // status, bytes ready
    case kGetCurrentProgramName: return 23;  // status, file name 20 bytes
    case kGetFirmwareVersion: return 7;      // status, protocol minor/major, firmware minor/major
    case kGetDeviceInfo: return 33;          // status, name 15, address 7, signal 4, free flash 4
    default: return 3;                       // status only (and "unknown command" for the rest)
  }
}

Bytes framed(const Bytes& telegram) {
  Bytes f;
  f.reserve(2 + telegram.size());
  f.push_back(lo(static_cast<uint16_t>(telegram.size())));
  f.push_back(hi(static_cast<uint16_t>(telegram.size())));
  for (uint8_t b : telegram) f.push_back(b);
  return f;
}

std::string Reply::text(size_t at, size_t n) const {
  std::string s;
  for (size_t i = at; i < at + n && i < bytes.size() && bytes[i] != 0; ++i) s.push_back(static_cast<char>(bytes[i]));
  return s;
}

bool TelegramSplitter::pop(Bytes& telegram) {
  if (buffer_.size() < 2) return false;
  const size_t n = buffer_[0] | (static_cast<size_t>(buffer_[1]) << 8);
  if (buffer_.size() < 2 + n) return false;
  telegram.assign(buffer_.begin() + 2, buffer_.begin() + static_cast<std::ptrdiff_t>(2 + n));
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(2 + n));
  return true;
}

}  // namespace nxtmap::emu::lego
