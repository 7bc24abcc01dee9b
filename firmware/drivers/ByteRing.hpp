#pragma once
#include <cstdint>

#include "firmware/board/Mmio.hpp"

namespace nxtmap::fw {

// A single-producer single-consumer byte ring of N bytes (a power of two): one side may run in an
// interrupt. Full rings drop new bytes and count them. A byte is stored before the head that publishes it
// moves, and loaded before the tail that frees its place moves (compiler barriers: buf_ is not volatile).
template <uint16_t N>
class ByteRing {
  static_assert(N > 0 && (N & (N - 1)) == 0 && N <= 32768, "N is a power of two");

 public:
  bool push(uint8_t b) {
    if (static_cast<uint16_t>(head_ - tail_) >= N) {
      ++dropped_;
      return false;
    }
    buf_[head_ & (N - 1)] = b;
    compilerBarrier();
    head_ = static_cast<uint16_t>(head_ + 1);
    return true;
  }
  bool pop(uint8_t& b) {
    if (head_ == tail_) return false;
    compilerBarrier();
    b = buf_[tail_ & (N - 1)];
    compilerBarrier();
    tail_ = static_cast<uint16_t>(tail_ + 1);
    return true;
  }
  // Consumer side: forgets everything pending.
  void clear() { tail_ = head_; }
  uint16_t size() const { return static_cast<uint16_t>(head_ - tail_); }
  uint16_t space() const { return static_cast<uint16_t>(N - size()); }
  // Pending bytes stored contiguously from the tail (for a DMA transfer).
  uint16_t contiguous() const {
    const uint16_t t = static_cast<uint16_t>(tail_ & (N - 1));
    const uint16_t n = size();
    return static_cast<uint16_t>(n < N - t ? n : N - t);
  }
  // The tail byte (start of contiguous()).
  const uint8_t* tailPointer() const { return &buf_[tail_ & (N - 1)]; }
  // The buffer's first byte: where the pending bytes go on after contiguous() ones when they wrap.
  const uint8_t* start() const { return buf_; }
  // Frees n bytes at the tail (after a DMA transfer of them).
  void drop(uint16_t n) { tail_ = static_cast<uint16_t>(tail_ + n); }
  uint32_t dropped() const { return dropped_; }

 private:
  uint8_t buf_[N] = {};
  volatile uint16_t head_ = 0, tail_ = 0;
  uint32_t dropped_ = 0;
};

}  // namespace nxtmap::fw
