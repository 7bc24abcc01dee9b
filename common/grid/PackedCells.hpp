#pragma once
#include <cstddef>
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// Bytes needed to store width*height values of `bits` bits each (bits = 1, 2 or 4).
constexpr size_t packedBytes(int width, int height, int bits) {
  return (static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(bits) + 7) / 8;
}
constexpr bool isPowerOfTwo(int v) { return v > 0 && (v & (v - 1)) == 0; }

// A torus of small unsigned values (BITS = 1, 2 or 4 per cell) over caller-owned storage.
// Any integer cell coordinate maps onto it by wrapping (the thesis's "(0,-1) = (0,4)"), so a map
// can grow from its origin into all four quadrants. Width and height are powers of two.
// Callers keep track of which window of coordinates is meaningful (see RoomGrid).
template <int BITS>
class PackedCells {
  static_assert(BITS == 1 || BITS == 2 || BITS == 4, "1, 2 or 4 bits per cell");

 public:
  // `storage` must hold packedBytes(width, height, BITS) bytes and outlive this object.
  PackedCells(uint8_t* storage, int16_t width, int16_t height) : data_(storage), width_(width), height_(height) {}

  int16_t width() const { return width_; }
  int16_t height() const { return height_; }
  size_t bytes() const { return packedBytes(width_, height_, BITS); }
  // The packed bytes (bytes() of them), for byte-wise comparisons of two tori of the same size.
  const uint8_t* data() const { return data_; }
  uint8_t* data() { return data_; }

  // Index of a cell on the torus, 0 .. width*height-1.
  uint32_t index(Cell c) const {
    const uint32_t ix = static_cast<uint32_t>(c.x) & static_cast<uint32_t>(width_ - 1);
    const uint32_t iy = static_cast<uint32_t>(c.y) & static_cast<uint32_t>(height_ - 1);
    return iy * static_cast<uint32_t>(width_) + ix;
  }
  uint8_t at(Cell c) const { return atIndex(index(c)); }
  void set(Cell c, uint8_t v) { setIndex(index(c), v); }

  uint8_t atIndex(uint32_t i) const {
    const uint32_t bit = i * BITS;
    return static_cast<uint8_t>((data_[bit >> 3] >> (bit & 7)) & kMask);
  }
  void setIndex(uint32_t i, uint8_t v) {
    const uint32_t bit = i * BITS;
    uint8_t& b = data_[bit >> 3];
    b = static_cast<uint8_t>((b & ~(kMask << (bit & 7))) | ((v & kMask) << (bit & 7)));
  }

  // Every cell to v. The byte pattern goes out through the compiler's memset (the brick's stores a word
  // at a time: a 2 KiB layer in about 1,000 instructions where a byte loop took 28,000).
  void fill(uint8_t v) {
    uint8_t pattern = 0;
    for (int k = 0; k < 8; k += BITS) pattern = static_cast<uint8_t>(pattern | ((v & kMask) << k));
    __builtin_memset(data_, pattern, bytes());
  }

  // Renames coordinates: the value at (x, y) moves to (x - sx, y - sy). In place, O(cells).
  void translate(int16_t sx, int16_t sy) {
    const uint32_t w = static_cast<uint32_t>(width_), h = static_cast<uint32_t>(height_);
    const uint32_t kx = static_cast<uint32_t>(sx) & (w - 1), ky = static_cast<uint32_t>(sy) & (h - 1);
    for (uint32_t y = 0; y < h; ++y) rotateLine(y * w, 1, w, kx);
    for (uint32_t x = 0; x < w; ++x) rotateLine(x, w, h, ky);
  }

 private:
  static constexpr uint8_t kMask = static_cast<uint8_t>((1u << BITS) - 1u);

  // Left rotation by k of the n values at first, first+stride, ... (three reversals).
  void rotateLine(uint32_t first, uint32_t stride, uint32_t n, uint32_t k) {
    if (k == 0) return;
    reverse(first, stride, 0, k);
    reverse(first, stride, k, n);
    reverse(first, stride, 0, n);
  }
  void reverse(uint32_t first, uint32_t stride, uint32_t lo, uint32_t hi) {
    while (lo + 1 < hi) {
      --hi;
      const uint32_t a = first + lo * stride, b = first + hi * stride;
      const uint8_t va = atIndex(a);
      setIndex(a, atIndex(b));
      setIndex(b, va);
      ++lo;
    }
  }

  uint8_t* data_;
  int16_t width_;
  int16_t height_;
};

}  // namespace nxtmap
