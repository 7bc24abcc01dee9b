#include "common/protocol/Telegram.hpp"

#include "common/protocol/Crc32.hpp"

namespace nxtmap::protocol {
namespace {

// One served LEGO command: its telegram size (0: variable, checked apart) and its reply size.
struct Served {
  bool system;
  uint8_t opcode;
  uint8_t commandSize;
  uint8_t replySize;
};
constexpr Served kServed[] = {
    {false, kLegoPlayTone, 6, kLegoStatusReplySize},
    {false, kLegoSetOutputState, 12, kLegoStatusReplySize},
    {false, kLegoGetOutputState, 3, kLegoOutputStateReplySize},
    {false, kLegoGetInputValues, 3, kLegoInputValuesReplySize},
    {false, kLegoMessageWrite, 0, kLegoWriteReplySize},
    {false, kLegoResetMotorPosition, 4, kLegoStatusReplySize},
    {false, kLegoGetBatteryLevel, kLegoBatteryCommandSize, kLegoBatteryReplySize},
    {false, kLegoStopSoundPlayback, 2, kLegoStatusReplySize},
    {false, kLegoKeepAlive, kLegoKeepAliveCommandSize, kLegoKeepAliveReplySize},
    {false, kLegoMessageRead, kLegoReadCommandSize, kLegoReadReplySize},
    {true, kLegoGetFirmwareVersion, 2, kLegoVersionReplySize},
    {true, kLegoSetBrickName, 0, kLegoStatusReplySize},
    {true, kLegoGetDeviceInfo, 2, kLegoDeviceInfoReplySize},
};

const Served* servedOf(uint8_t type, uint8_t opcode) {
  const bool system = (type & 0x7F) == kTypeSystem;
  for (const Served& s : kServed) {
    if (s.system == system && s.opcode == opcode) return &s;
  }
  return nullptr;
}

// Any opcode a reply can carry: the served ones of either kind.
const Served* servedReplyOf(uint8_t opcode) {
  for (const Served& s : kServed) {
    if (s.opcode == opcode) return &s;
  }
  return nullptr;
}

bool nxtmapPacketValid(const uint8_t* t, size_t size) {
  if (size < kPacketHeader + kPacketTrailer) return false;
  const size_t body = size - kPacketTrailer;
  const uint32_t stored = static_cast<uint32_t>(t[body]) | (static_cast<uint32_t>(t[body + 1]) << 8) |
                          (static_cast<uint32_t>(t[body + 2]) << 16) | (static_cast<uint32_t>(t[body + 3]) << 24);
  return crc32(t, body) == stored;
}

bool variableCommandKnown(const uint8_t* t, size_t size) {
  if (t[1] == kLegoSetBrickName) return size == 2 + kLegoNameChars || size == 2 + kLegoNameChars + 1;
  // MESSAGE_WRITE: [inbox][n][n bytes, NUL last].
  if (size < 5) return false;
  const size_t n = t[3];
  return n >= 1 && n <= kLegoMaxMessage && size == 4 + n && t[size - 1] == 0;
}

}  // namespace

bool telegramValid(const uint8_t* t, size_t size) {
  if (size < 2 || size > kMaxTelegram) return false;
  if (t[0] == kTypeNxtmap) return nxtmapPacketValid(t, size);
  return isLegoType(t[0]);
}

bool legoTelegramKnown(const uint8_t* t, size_t size) {
  if (size < 2 || size > kMaxTelegram) return false;
  if (t[0] == kTypeReply) {
    const Served* s = servedReplyOf(t[1]);
    return size == kLegoStatusReplySize || (s != nullptr && size == s->replySize);
  }
  if (!isLegoCommandType(t[0])) return false;
  const Served* s = servedOf(t[0], t[1]);
  if (s == nullptr) return false;
  return s->commandSize == 0 ? variableCommandKnown(t, size) : size == s->commandSize;
}

size_t legoReplySize(uint8_t type, uint8_t opcode) {
  const Served* s = servedOf(type, opcode);
  return s == nullptr ? 0 : s->replySize;
}

bool frameTelegram(const uint8_t* telegram, size_t size, Frame& out) {
  if (size > kMaxTelegram) return false;
  out.bytes[0] = static_cast<uint8_t>(size);
  out.bytes[1] = static_cast<uint8_t>(size >> 8);
  for (size_t i = 0; i < size; ++i) out.bytes[kLengthPrefix + i] = telegram[i];
  out.size = static_cast<uint8_t>(kLengthPrefix + size);
  return true;
}

}  // namespace nxtmap::protocol
