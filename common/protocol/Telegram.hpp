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

// Whether `size` bytes can be a whole telegram this link serves: an nxtmap packet with a good
// CRC, a served LEGO direct command of exactly its size (MESSAGE_WRITE: a NUL-terminated
// message of 1..59 bytes), or a LEGO reply of a served opcode. Anything else is noise.
bool telegramValid(const uint8_t* telegram, size_t size);

// Wraps a telegram into a frame (length prefix). False when it does not fit.
bool frameTelegram(const uint8_t* telegram, size_t size, Frame& out);

}  // namespace nxtmap::protocol
