#include "host/emu/Pwm.hpp"

namespace nxtmap::emu {

uint64_t Pwm::clockDivider(uint32_t cpre) const {
  if (cpre <= 10) return uint64_t{1} << cpre;
  if (cpre > 12) return 0;
  const uint32_t half = cpre == 11 ? mr_ & 0xFFFF : mr_ >> 16;  // DIVx bits 0-7, PREx bits 8-11
  const uint32_t div = half & 0xFF, pre = (half >> 8) & 0xF;
  if (div == 0 || pre > 10) return 0;  // DIVx 0: clock x off
  return (uint64_t{1} << pre) * div;
}

uint64_t Pwm::periodCycles(int n) const {
  const Channel& c = ch_[static_cast<size_t>(n)];
  const uint64_t div = clockDivider(c.cmr & 0xF);
  return div * c.cprd * (((c.cmr >> 8) & 1) ? 2 : 1);
}

void Pwm::endPeriods(int n, uint64_t now) {
  Channel& c = ch_[static_cast<size_t>(n)];
  const uint64_t period = periodCycles(n);
  if (!((sr_ >> n) & 1) || period == 0 || now < c.start + period) return;
  c.start += (now - c.start) / period * period;
  isr_ |= 1u << n;
  if (c.update) {  // CPD: 0 duty, 1 period
    ((c.cmr >> 10) & 1 ? c.cprd : c.cdty) = c.cupd;
    c.update = false;
  }
}

uint64_t Pwm::nextEventAt() const {
  uint64_t t = kNever;
  for (int n = 0; n < 4; ++n) {
    const uint64_t period = periodCycles(n);
    if (!((sr_ >> n) & 1) || period == 0 || !((imr_ >> n) & 1) || ((isr_ >> n) & 1)) continue;
    const uint64_t end = ch_[static_cast<size_t>(n)].start + period;
    if (end < t) t = end;
  }
  return t;
}

void Pwm::advanceTo(uint64_t now) {
  for (int n = 0; n < 4; ++n) endPeriods(n, now);
}

bool Pwm::read(uint32_t off, uint32_t& v) {
  if (off >= 0x200 && off < 0x280) {
    Channel& c = ch_[(off - 0x200) / 0x20];
    const int n = static_cast<int>((off - 0x200) / 0x20);
    switch (off % 0x20) {
      case 0x00: v = c.cmr; return true;
      case 0x04: v = c.cdty; return true;
      case 0x08: v = c.cprd; return true;
      case 0x0C: {
        const uint64_t div = clockDivider(c.cmr & 0xF);
        advanceTo(clock_.now);
        v = ((sr_ >> n) & 1) && div ? static_cast<uint32_t>((clock_.now - c.start) / div) : 0u;
        return true;
      }
      default: return false;
    }
  }
  switch (off) {
    case 0x00: v = mr_; return true;
    case 0x0C: v = sr_; return true;
    case 0x18: v = imr_; return true;
    case 0x1C:
      advanceTo(clock_.now);
      v = isr_;
      isr_ = 0;
      return true;
    default: return false;
  }
}

bool Pwm::write(uint32_t off, uint32_t v) {
  if (off >= 0x200 && off < 0x280) {
    Channel& c = ch_[(off - 0x200) / 0x20];
    switch (off % 0x20) {
      case 0x00: c.cmr = v & 0x70F; return true;
      case 0x04: c.cdty = v; return true;
      case 0x08: c.cprd = v; return true;
      case 0x10:
        c.cupd = v;
        c.update = true;
        return true;
      default: return false;
    }
  }
  switch (off) {
    case 0x00: mr_ = v & 0x0FFF0FFF; return true;
    case 0x04:
      for (int n = 0; n < 4; ++n)
        if (((v >> n) & 1) && !((sr_ >> n) & 1)) ch_[static_cast<size_t>(n)].start = clock_.now;
      sr_ |= v & 0xF;
      return true;
    case 0x08: sr_ &= ~v; return true;
    case 0x10: imr_ |= v & 0xF; return true;
    case 0x14: imr_ &= ~v; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
