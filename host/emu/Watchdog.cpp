#include "host/emu/Watchdog.hpp"

namespace nxtmap::emu {

uint64_t Watchdog::nextEventAt() const {
  if (mr_ & (1u << 15)) return kNever;     // WDDIS
  if (!(mr_ & (1u << 13))) return kNever;  // no WDRSTEN: no reset (interrupt-only mode not used)
  return restartedAt_ + timeoutCycles();
}

bool Watchdog::read(uint32_t off, uint32_t& v) {
  switch (off) {
    case 0x4: v = mr_; return true;
    case 0x8: v = 0; return true;
    default: return false;
  }
}

bool Watchdog::write(uint32_t off, uint32_t v) {
  switch (off) {
    case 0x0:
      if ((v >> 24) == 0xA5 && (v & 1)) {
        if (clock_.now - restartedAt_ > longestGap_) longestGap_ = clock_.now - restartedAt_;
        restartedAt_ = clock_.now;
      }
      return true;
    case 0x4:
      if (!written_) {
        mr_ = v;
        written_ = true;
        restartedAt_ = clock_.now;
      }
      return true;  // write-once: later writes are ignored, as on the chip
    default: return false;
  }
}

}  // namespace nxtmap::emu
