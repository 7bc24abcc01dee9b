#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/Telegram.hpp"

namespace nxtmap::protocol {

// What the decoder has seen, for status reports and tests.
struct DecoderCounters {
  uint32_t bytes = 0;      // bytes pushed
  uint32_t telegrams = 0;  // valid telegrams delivered
  uint32_t skipped = 0;    // bytes thrown away while resynchronising (noise, broken frames)
};

// Byte-at-a-time decoder of the length-prefixed stream [length LE16][type][opcode][...].
//
// In step (at the start, after a reset and after every telegram delivered) the length is trusted:
// a telegram of a LEGO type (LegoFormat.hpp) of 2..kMaxTelegram bytes is consumed whole and
// delivered, understood or not, so an unknown LEGO command can never swallow the frames after it;
// an nxtmap packet must carry a good CRC. Anything else (a length out of range, an unknown type, a
// bad CRC) is damage: the decoder drops one byte and resynchronises, and until it delivers again it
// accepts only what can be checked: nxtmap packets (CRC) and LEGO telegrams whose layout is known
// to the byte (legoTelegramKnown). Memory: one maximum frame.
//
//   decoder.push(byte);
//   while (decoder.pop(telegram)) handle(telegram);
class FrameDecoder {
 public:
  // Appends a byte. Call pop() until it returns false after every push.
  void push(uint8_t byte);
  // Delivers the next valid telegram, if the buffered bytes hold one.
  bool pop(Telegram& out);
  // Forgets buffered bytes (after a disconnect).
  void reset();

  const DecoderCounters& counters() const { return counters_; }
  size_t buffered() const { return count_; }

 private:
  uint8_t at(size_t i) const { return buf_[(head_ + i) % kMaxFrame]; }
  // Whether the bytes at the front can start a frame (length, type); false: damage.
  bool plausibleStart() const;
  void drop(size_t n);

  uint8_t buf_[kMaxFrame] = {};
  size_t head_ = 0;     // index of the oldest byte
  size_t count_ = 0;    // bytes buffered
  bool inStep_ = true;  // false from damage until the next telegram delivered
  DecoderCounters counters_;
};

}  // namespace nxtmap::protocol
