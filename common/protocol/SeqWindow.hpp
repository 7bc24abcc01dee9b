#pragma once
#include <cstdint>

namespace nxtmap::protocol {

// The receiver's record of reliable sequence numbers: the newest one and a 16-bit mask of the
// 16 before it. It decides duplicates (so no command runs twice) and produces ack/ackMask.
// Anything more than 16 behind the newest counts as already seen (a very late copy).
class SeqWindow {
 public:
  // Whether `seq` was recorded already (or is too old to tell). seq 0 is never "seen".
  bool seen(uint16_t seq) const;
  // Records `seq` (a no-op for 0).
  void record(uint16_t seq);
  void reset() {
    any_ = false;
    newest_ = 0;
    mask_ = 0;
  }

  uint16_t ack() const { return any_ ? newest_ : 0; }
  uint16_t ackMask() const { return any_ ? mask_ : 0; }

 private:
  bool any_ = false;
  uint16_t newest_ = 0;
  uint16_t mask_ = 0;
};

}  // namespace nxtmap::protocol
