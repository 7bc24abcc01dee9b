#include "host/emu/Pit.hpp"

namespace nxtmap::emu {

uint64_t Pit::periods() const {
  const uint64_t t = running_ ? clock_.now : frozenAt_;
  return t >= start_ ? (t - start_) / periodCycles() : 0;
}

uint32_t Pit::valueRegister() const {
  const uint64_t t = running_ ? clock_.now : frozenAt_;
  const uint64_t cpiv = t >= start_ ? ((t - start_) % periodCycles()) / 16 : 0;
  const uint64_t picnt = periodsUnread() & 0xFFF;
  return static_cast<uint32_t>((picnt << 20) | cpiv);
}

uint64_t Pit::nextEventAt() const {
  if (!running_ || !(mr_ & kItEn)) return kNever;  // every period boundary (also while unread: cheap, no re-plan)
  return start_ + (periods() + 1) * periodCycles();
}

bool Pit::read(uint32_t off, uint32_t& v) {
  switch (off) {
    case 0x0: v = mr_; return true;
    case 0x4: v = periodsUnread() > 0 ? 1u : 0u; return true;
    case 0x8:  // PIVR: read acknowledges
      v = valueRegister();
      periodsRead_ = periods();
      return true;
    case 0xC: v = valueRegister(); return true;
    default: return false;
  }
}

bool Pit::write(uint32_t off, uint32_t v) {
  if (off != 0) return false;
  const bool en = (v & kEn) != 0;
  const bool pivChanged = (v & 0xFFFFF) != (mr_ & 0xFFFFF);
  if (en && (!running_ || pivChanged)) {
    start_ = clock_.now;
    periodsRead_ = 0;
    running_ = true;
  } else if (!en && running_) {
    frozenAt_ = clock_.now;
    running_ = false;
  }
  mr_ = v & (0xFFFFF | kEn | kItEn);
  return true;
}

}  // namespace nxtmap::emu
