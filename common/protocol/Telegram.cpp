#include "common/protocol/Telegram.hpp"

#include "common/protocol/Crc32.hpp"

namespace nxtmap::protocol {
namespace {

bool nxtmapPacketValid(const uint8_t* t, size_t size) {
  if (size < kPacketHeader + kPacketTrailer) return false;
  const size_t body = size - kPacketTrailer;
  const uint32_t stored = static_cast<uint32_t>(t[body]) | (static_cast<uint32_t>(t[body + 1]) << 8) |
                          (static_cast<uint32_t>(t[body + 2]) << 16) | (static_cast<uint32_t>(t[body + 3]) << 24);
  return crc32(t, body) == stored;
}

bool legoCommandValid(const uint8_t* t, size_t size) {
  switch (t[1]) {
    case kLegoGetBatteryLevel: return size == kLegoBatteryCommandSize;
    case kLegoKeepAlive: return size == kLegoKeepAliveCommandSize;
    case kLegoMessageRead:
      return size == kLegoReadCommandSize && t[2] < 2 * kLegoMailboxes && t[3] < kLegoMailboxes && t[4] <= 1;
    case kLegoMessageWrite: {
      if (size < 5 || t[2] >= kLegoMailboxes) return false;
      const size_t n = t[3];
      return n >= 1 && n <= kLegoMaxMessage && size == 4 + n && t[size - 1] == 0;
    }
    default: return false;
  }
}

bool legoReplyValid(const uint8_t* t, size_t size) {
  switch (t[1]) {
    case kLegoGetBatteryLevel: return size == kLegoBatteryReplySize;
    case kLegoKeepAlive: return size == kLegoKeepAliveReplySize;
    case kLegoMessageRead: return size == kLegoReadReplySize && t[3] < kLegoMailboxes && t[4] <= kLegoMaxMessage;
    case kLegoMessageWrite: return size == kLegoWriteReplySize;
    default: return false;
  }
}

}  // namespace

bool telegramValid(const uint8_t* t, size_t size) {
  if (size < 2 || size > kMaxTelegram) return false;
  switch (t[0]) {
    case kTypeNxtmap: return nxtmapPacketValid(t, size);
    case kTypeDirect:
    case kTypeDirectNoReply: return legoCommandValid(t, size);
    case kTypeReply: return legoReplyValid(t, size);
    default: return false;
  }
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
