#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/WireFormat.hpp"

namespace nxtmap::protocol {

// One telegram as it arrived (without the 2-byte length prefix): [type][opcode][...].
struct Telegram {
  uint8_t bytes[kMaxTelegram] = {};
  uint8_t size = 0;

  uint8_t type() const { return size > 0 ? bytes[0] : 0; }
  uint8_t opcode() const { return size > 1 ? bytes[1] : 0; }
};

// A frame ready for the wire: length prefix + telegram.
struct Frame {
  uint8_t bytes[kMaxFrame] = {};
  uint8_t size = 0;
};

// LEGO's telegram types: commands (direct, system; reply wanted or not) and replies.
constexpr bool isLegoCommandType(uint8_t type) {
  return type == kTypeDirect || type == kTypeSystem || type == kTypeDirectNoReply || type == kTypeSystemNoReply;
}
constexpr bool isLegoType(uint8_t type) { return isLegoCommandType(type) || type == kTypeReply; }
// Whether a LEGO command of this type wants a reply (bit 7 clear).
constexpr bool legoReplyWanted(uint8_t type) { return (type & 0x80) == 0; }

// Whether `size` bytes are a whole telegram the link delivers: an nxtmap packet with a good CRC,
// or any telegram of a LEGO type (2..kMaxTelegram bytes), understood or not.
bool telegramValid(const uint8_t* telegram, size_t size);

// Whether `size` bytes are a LEGO telegram whose layout is known to the byte: a served command of
// exactly its size (MESSAGE_WRITE: 1..59 bytes ending with NUL; SET_BRICK_NAME: 15 or 16 name
// bytes), a reply of a served opcode of exactly its reply size, or a 3-byte status reply. The
// decoder trusts only these while it resynchronises after damage.
bool legoTelegramKnown(const uint8_t* telegram, size_t size);

// The reply size of a served LEGO command (0: not served; the reply is then [02][op][0xBE]).
size_t legoReplySize(uint8_t type, uint8_t opcode);

// Wraps a telegram into a frame (length prefix). False when it does not fit.
bool frameTelegram(const uint8_t* telegram, size_t size, Frame& out);

}  // namespace nxtmap::protocol
