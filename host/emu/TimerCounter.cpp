#include "host/emu/TimerCounter.hpp"

namespace nxtmap::emu {

namespace {
constexpr uint32_t kCpcs = 1u << 4, kClksta = 1u << 16;
}

uint64_t TimerCounter::divider(const Channel& c) const {
  switch (c.cmr & 7) {
    case 0: return 2;
    case 1: return 8;
    case 2: return 32;
    case 3: return 128;
    case 4: return 1024;
    default: return 0;  // external clocks: not modelled (never counts)
  }
}

bool TimerCounter::rcTrigger(const Channel& c) const {
  const bool wave = (c.cmr >> 15) & 1;
  return wave ? ((c.cmr >> 13) & 3) == 2 : ((c.cmr >> 14) & 1) != 0;
}

uint64_t TimerCounter::compares(const Channel& c) const {
  const uint64_t div = divider(c);
  if (!c.running || div == 0 || c.rc == 0) return 0;
  const uint64_t ticks = (clock_.now - c.start) / div;
  if (rcTrigger(c)) return ticks / c.rc;
  return ticks >= c.rc ? 1 + (ticks - c.rc) / 65536 : 0;  // free-running 16-bit counter passes RC once per wrap
}

uint32_t TimerCounter::counter(const Channel& c) const {
  const uint64_t div = divider(c);
  if (!c.running || div == 0) return 0;
  const uint64_t ticks = (clock_.now - c.start) / div;
  return static_cast<uint32_t>(rcTrigger(c) && c.rc ? ticks % c.rc : ticks & 0xFFFF);
}

bool TimerCounter::irqLine(int i) const {
  const Channel& c = ch_[static_cast<size_t>(i)];
  return (c.imr & kCpcs) && compares(c) > c.comparesRead;
}

uint64_t TimerCounter::nextEventAt() const {
  uint64_t t = kNever;
  for (const Channel& c : ch_) {
    const uint64_t div = divider(c);
    if (!c.running || div == 0 || c.rc == 0 || !(c.imr & kCpcs)) continue;
    if (!rcTrigger(c)) continue;
    const uint64_t next = c.start + (compares(c) + 1) * c.rc * div;
    if (next < t) t = next;
  }
  return t;
}

bool TimerCounter::read(uint32_t off, uint32_t& v) {
  if (off >= 0xC0) {
    if (off == 0xC4) {
      v = 0;
      return true;
    }  // BMR
    return false;
  }
  Channel& c = ch_[off / 0x40];
  switch (off % 0x40) {
    case 0x04: v = c.cmr; return true;
    case 0x10: v = counter(c); return true;
    case 0x14: v = c.ra; return true;
    case 0x18: v = c.rb; return true;
    case 0x1C: v = c.rc; return true;
    case 0x20: {
      const uint64_t n = compares(c);
      v = (n > c.comparesRead ? kCpcs : 0u) | (c.running ? kClksta : 0u);
      c.comparesRead = n;
      return true;
    }
    case 0x2C: v = c.imr; return true;
    default: return false;
  }
}

bool TimerCounter::write(uint32_t off, uint32_t v) {
  if (off >= 0xC0) return off == 0xC0 || off == 0xC4;  // BCR (SYNC) / BMR: accepted
  Channel& c = ch_[off / 0x40];
  switch (off % 0x40) {
    case 0x00:
      if (v & 2) c.running = false;  // CLKDIS wins over CLKEN
      if ((v & 1) && !(v & 2)) {
        if (!c.running) {
          c.running = true;
          c.start = clock_.now;
          c.comparesRead = 0;
        }
      }
      if ((v & 4) && c.running) {
        c.start = clock_.now;
        c.comparesRead = 0;
      }  // SWTRG: restart at 0
      return true;
    case 0x04: c.cmr = v; return true;
    case 0x14: c.ra = v & 0xFFFF; return true;
    case 0x18: c.rb = v & 0xFFFF; return true;
    case 0x1C: c.rc = v & 0xFFFF; return true;
    case 0x24: c.imr |= v; return true;
    case 0x28: c.imr &= ~v; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
