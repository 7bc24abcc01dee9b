#include "common/protocol/FrameDecoder.hpp"

namespace nxtmap::protocol {

void FrameDecoder::push(uint8_t byte) {
  ++counters_.bytes;
  if (count_ == kMaxFrame) drop(1);  // the caller did not pop: the oldest byte cannot start a frame now
  buf_[(head_ + count_) % kMaxFrame] = byte;
  ++count_;
}

bool FrameDecoder::plausibleStart() const {
  const size_t length = static_cast<size_t>(at(0)) | (static_cast<size_t>(at(1)) << 8);
  if (length < 2 || length > kMaxTelegram) return false;
  return count_ < 3 || at(2) == kTypeNxtmap || isLegoType(at(2));
}

bool FrameDecoder::pop(Telegram& out) {
  while (count_ >= kLengthPrefix) {
    if (!plausibleStart()) {
      drop(1);
      continue;
    }
    const size_t length = static_cast<size_t>(at(0)) | (static_cast<size_t>(at(1)) << 8);
    if (count_ < kLengthPrefix + length) return false;  // wait for the rest
    for (size_t i = 0; i < length; ++i) out.bytes[i] = at(kLengthPrefix + i);
    const bool lego = isLegoType(out.bytes[0]);
    const bool whole = lego ? (inStep_ || legoTelegramKnown(out.bytes, length)) : telegramValid(out.bytes, length);
    if (!whole) {
      drop(1);
      continue;
    }
    out.size = static_cast<uint8_t>(length);
    head_ = (head_ + kLengthPrefix + length) % kMaxFrame;
    count_ -= kLengthPrefix + length;
    ++counters_.telegrams;
    inStep_ = true;
    return true;
  }
  return false;
}

void FrameDecoder::reset() {
  counters_.skipped += static_cast<uint32_t>(count_);
  head_ = 0;
  count_ = 0;
  inStep_ = true;
}

void FrameDecoder::drop(size_t n) {
  head_ = (head_ + n) % kMaxFrame;
  count_ -= n;
  counters_.skipped += static_cast<uint32_t>(n);
  inStep_ = false;
}

}  // namespace nxtmap::protocol
