#pragma once
#include <cstddef>
#include <cstdint>

namespace nxtmap::protocol {

// Writes explicit little-endian fields into a caller-owned buffer. Writing past the end sets
// a sticky failure (ok() == false) and writes nothing more.
class ByteWriter {
 public:
  ByteWriter(uint8_t* out, size_t capacity) : out_(out), capacity_(capacity) {}

  void u8(uint8_t v) {
    if (!room(1)) return;
    out_[size_++] = v;
  }
  void u16(uint16_t v) {
    if (!room(2)) return;
    out_[size_++] = static_cast<uint8_t>(v);
    out_[size_++] = static_cast<uint8_t>(v >> 8);
  }
  void i16(int16_t v) { u16(static_cast<uint16_t>(v)); }
  void u32(uint32_t v) {
    if (!room(4)) return;
    for (int k = 0; k < 4; ++k) out_[size_++] = static_cast<uint8_t>(v >> (8 * k));
  }
  void bytes(const uint8_t* data, size_t n) {
    if (!room(n)) return;
    for (size_t i = 0; i < n; ++i) out_[size_++] = data[i];
  }
  // Overwrites a 16-bit field written earlier at `at`.
  void patchU16(size_t at, uint16_t v) {
    if (at + 2 > size_) {
      ok_ = false;
      return;
    }
    out_[at] = static_cast<uint8_t>(v);
    out_[at + 1] = static_cast<uint8_t>(v >> 8);
  }

  bool ok() const { return ok_; }
  size_t size() const { return size_; }
  size_t remaining() const { return capacity_ - size_; }
  uint8_t* data() { return out_; }

 private:
  bool room(size_t n) {
    if (!ok_ || capacity_ - size_ < n) {
      ok_ = false;
      return false;
    }
    return true;
  }

  uint8_t* out_;
  size_t capacity_;
  size_t size_ = 0;
  bool ok_ = true;
};

}  // namespace nxtmap::protocol
