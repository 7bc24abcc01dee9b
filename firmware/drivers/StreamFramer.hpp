#pragma once
#include <cstdint>

namespace nxtmap::fw {

// The NXT's data-mode framing over Bluetooth: each telegram is preceded by its length as 2 bytes,
// little-endian (what nxt-python and LEGO's firmware use). Encoding plus a byte-at-a-time decoder
// with a fixed maximum telegram size; longer telegrams are skipped whole and counted.
constexpr uint16_t kStreamMaxTelegram = 128;

// Writes [len lo][len hi][bytes] into out (n + 2 bytes); returns the byte count, 0 if too long.
inline uint16_t encodeStreamFrame(const uint8_t* bytes, uint16_t n, uint8_t* out) {
  if (n == 0 || n > kStreamMaxTelegram) return 0;
  out[0] = static_cast<uint8_t>(n & 0xFF);
  out[1] = static_cast<uint8_t>(n >> 8);
  for (uint16_t i = 0; i < n; ++i) out[2 + i] = bytes[i];
  return static_cast<uint16_t>(n + 2);
}

class StreamDecoder {
 public:
  // Feeds one byte; true when a whole telegram is in telegram()/length().
  bool push(uint8_t b) {
    switch (state_) {
      case State::Low:
        want_ = b;
        state_ = State::High;
        return false;
      case State::High:
        want_ = static_cast<uint16_t>(want_ | (b << 8));
        have_ = 0;
        if (want_ == 0) {
          state_ = State::Low;
          return false;
        }
        state_ = want_ > kStreamMaxTelegram ? State::Skip : State::Body;
        if (state_ == State::Skip) ++oversized_;
        return false;
      case State::Body:
        buf_[have_++] = b;
        if (have_ < want_) return false;
        state_ = State::Low;
        return true;
      case State::Skip:
        if (++have_ >= want_) state_ = State::Low;
        return false;
    }
    return false;
  }
  void reset() { state_ = State::Low; }
  const uint8_t* telegram() const { return buf_; }
  uint16_t length() const { return want_; }
  uint32_t oversized() const { return oversized_; }

 private:
  enum class State : uint8_t { Low, High, Body, Skip };
  uint8_t buf_[kStreamMaxTelegram] = {};
  uint16_t want_ = 0, have_ = 0;
  uint32_t oversized_ = 0;
  State state_ = State::Low;
};

}  // namespace nxtmap::fw
