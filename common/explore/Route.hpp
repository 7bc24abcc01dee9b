#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// A fixed-capacity sequence of one-cell moves (absolute directions) the robot is following.
class Route {
 public:
  static constexpr uint8_t kCapacity = 96;

  void clear() { size_ = next_ = 0; }
  bool empty() const { return next_ >= size_; }
  uint8_t remaining() const { return static_cast<uint8_t>(size_ - next_); }
  bool push(Dir d) {
    if (size_ >= kCapacity) return false;
    dirs_[size_++] = d;
    return true;
  }
  Dir front() const { return dirs_[next_]; }
  void pop() {
    if (next_ < size_) ++next_;
  }
  // Replaces the contents by the first n moves of `dirs` (n <= kCapacity).
  void assign(const Dir* dirs, uint8_t n) {
    clear();
    for (uint8_t i = 0; i < n; ++i) push(dirs[i]);
  }

 private:
  Dir dirs_[kCapacity] = {};
  uint8_t size_ = 0;
  uint8_t next_ = 0;
};

}  // namespace nxtmap
