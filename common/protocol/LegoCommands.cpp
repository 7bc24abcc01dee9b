#include "common/protocol/LegoCommands.hpp"

namespace nxtmap::protocol {
namespace {

bool frameFrom(const uint8_t* telegram, size_t size, Frame& out) { return frameTelegram(telegram, size, out); }

}  // namespace

bool encodeGetBatteryLevel(Frame& out) {
  const uint8_t t[] = {kTypeDirect, kLegoGetBatteryLevel};
  return frameFrom(t, sizeof(t), out);
}

bool encodeKeepAlive(Frame& out) {
  const uint8_t t[] = {kTypeDirect, kLegoKeepAlive};
  return frameFrom(t, sizeof(t), out);
}

bool encodeMessageWrite(uint8_t box, const char* text, Frame& out) {
  size_t n = 0;
  while (text[n] != '\0') {
    if (++n >= kLegoMaxMessage) return false;
  }
  if (box >= kLegoMailboxes) return false;
  uint8_t t[4 + kLegoMaxMessage] = {kTypeDirect, kLegoMessageWrite, box, static_cast<uint8_t>(n + 1)};
  for (size_t i = 0; i < n; ++i) t[4 + i] = static_cast<uint8_t>(text[i]);
  t[4 + n] = 0;
  return frameFrom(t, 4 + n + 1, out);
}

bool encodeMessageRead(uint8_t remoteBox, uint8_t localBox, bool remove, Frame& out) {
  if (remoteBox >= kLegoMailboxes || localBox >= kLegoMailboxes) return false;
  const uint8_t t[] = {kTypeDirect, kLegoMessageRead, remoteBox, localBox, static_cast<uint8_t>(remove ? 1 : 0)};
  return frameFrom(t, sizeof(t), out);
}

bool decodeBatteryReply(const Telegram& t, uint8_t& status, uint16_t& millivolts) {
  if (t.size != kLegoBatteryReplySize || t.type() != kTypeReply || t.opcode() != kLegoGetBatteryLevel) return false;
  status = t.bytes[2];
  millivolts = static_cast<uint16_t>(t.bytes[3] | (t.bytes[4] << 8));
  return true;
}

bool decodeKeepAliveReply(const Telegram& t, uint8_t& status, uint32_t& sleepLimitMs) {
  if (t.size != kLegoKeepAliveReplySize || t.type() != kTypeReply || t.opcode() != kLegoKeepAlive) return false;
  status = t.bytes[2];
  sleepLimitMs = 0;
  for (int k = 0; k < 4; ++k) sleepLimitMs |= static_cast<uint32_t>(t.bytes[3 + k]) << (8 * k);
  return true;
}

bool decodeMessageWriteReply(const Telegram& t, uint8_t& status) {
  if (t.size != kLegoWriteReplySize || t.type() != kTypeReply || t.opcode() != kLegoMessageWrite) return false;
  status = t.bytes[2];
  return true;
}

bool decodeMessageReadReply(const Telegram& t, uint8_t& status, uint8_t& box, char (&text)[kLegoMaxMessage + 1]) {
  if (t.size != kLegoReadReplySize || t.type() != kTypeReply || t.opcode() != kLegoMessageRead) return false;
  status = t.bytes[2];
  box = t.bytes[3];
  const uint8_t size = t.bytes[4];
  if (size > kLegoMaxMessage) return false;
  size_t n = 0;
  for (; n < size && t.bytes[5 + n] != 0; ++n) text[n] = static_cast<char>(t.bytes[5 + n]);
  text[n] = '\0';
  return true;
}

}  // namespace nxtmap::protocol
