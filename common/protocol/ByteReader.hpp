#pragma once
#include <cstddef>
#include <cstdint>

namespace nxtmap::protocol {

// Reads explicit little-endian fields from a byte range. Reading past the end sets a sticky
// failure (ok() == false) and yields zeros: decoders read every field, then check ok() once.
class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  uint8_t u8() {
    if (!room(1)) return 0;
    return data_[pos_++];
  }
  uint16_t u16() {
    if (!room(2)) return 0;
    const uint16_t v = static_cast<uint16_t>(data_[pos_] | (data_[pos_ + 1] << 8));
    pos_ += 2;
    return v;
  }
  int16_t i16() { return static_cast<int16_t>(u16()); }
  uint32_t u32() {
    if (!room(4)) return 0;
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= static_cast<uint32_t>(data_[pos_ + static_cast<size_t>(k)]) << (8 * k);
    pos_ += 4;
    return v;
  }
  // Copies n bytes into `out` (nothing on failure).
  void bytes(uint8_t* out, size_t n) {
    if (!room(n)) return;
    for (size_t i = 0; i < n; ++i) out[i] = data_[pos_ + i];
    pos_ += n;
  }

  bool ok() const { return ok_; }
  bool atEnd() const { return pos_ == size_; }
  size_t remaining() const { return size_ - pos_; }
  size_t position() const { return pos_; }

 private:
  bool room(size_t n) {
    if (!ok_ || size_ - pos_ < n) {
      ok_ = false;
      return false;
    }
    return true;
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  bool ok_ = true;
};

}  // namespace nxtmap::protocol
