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

// Byte-at-a-time decoder of the length-prefixed stream. It survives dropped, corrupted and
// duplicated bytes: when the bytes at the front cannot start a valid frame (bad length, bad
// type, bad CRC, wrong LEGO size) it drops one byte and tries again from the next, so it
// resynchronises on the next intact frame. Memory: one maximum frame.
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
  void drop(size_t n);

  uint8_t buf_[kMaxFrame] = {};
  size_t head_ = 0;   // index of the oldest byte
  size_t count_ = 0;  // bytes buffered
  DecoderCounters counters_;
};

}  // namespace nxtmap::protocol
