#include "host/emu/TimerCounter.hpp"

namespace nxtmap::emu {

namespace {
constexpr uint32_t kWave = 1u << 15, kAbetrg = 1u << 10, kLdbstop = 1u << 6, kLdbdis = 1u << 7;
constexpr uint32_t kLatchedBits =
    TimerCounter::kLovrs | TimerCounter::kLdras | TimerCounter::kLdrbs | TimerCounter::kEtrgs;

// Whether an edge field (0 none, 1 rising, 2 falling, 3 both) selects this edge.
bool edgeSelected(uint32_t field, bool rising) { return field == 3 || field == (rising ? 1u : 2u); }
}  // namespace

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
  const bool wave = (c.cmr & kWave) != 0;
  return wave ? ((c.cmr >> 13) & 3) == 2 : ((c.cmr >> 14) & 1) != 0;
}

uint64_t TimerCounter::compares(const Channel& c) const {
  const uint64_t div = divider(c);
  if (!c.running || div == 0 || c.rc == 0) return 0;
  const uint64_t ticks = (clock_.now - c.start) / div;
  if (rcTrigger(c)) return ticks / c.rc;
  return ticks >= c.rc ? 1 + (ticks - c.rc) / 65536 : 0;  // free-running 16-bit counter passes RC once per wrap
}

uint64_t TimerCounter::overflows(const Channel& c) const {
  const uint64_t div = divider(c);
  if (!c.running || div == 0 || (rcTrigger(c) && c.rc != 0)) return 0;
  return (clock_.now - c.start) / div / 65536;
}

uint32_t TimerCounter::counter(const Channel& c) const {
  const uint64_t div = divider(c);
  if (!c.running || div == 0) return 0;
  const uint64_t ticks = (clock_.now - c.start) / div;
  return static_cast<uint32_t>(rcTrigger(c) && c.rc ? ticks % c.rc : ticks & 0xFFFF);
}

uint32_t TimerCounter::status(const Channel& c) const {
  return c.latched | (compares(c) > c.comparesRead ? kCpcs : 0u) | (overflows(c) > c.overflowsRead ? kCovfs : 0u) |
         (c.running ? kClksta : 0u) | (c.tioa ? kMtioa : 0u);
}

// Sampled by the AIC at every event: only the enabled sources are computed.
bool TimerCounter::irqLine(int i) const {
  const Channel& c = ch_[static_cast<size_t>(i)];
  if ((c.imr & 0xFF) == 0) return false;
  if (c.latched & c.imr) return true;
  if ((c.imr & kCpcs) && compares(c) > c.comparesRead) return true;
  return (c.imr & kCovfs) && overflows(c) > c.overflowsRead;
}

uint64_t TimerCounter::nextEventAt() const {
  uint64_t t = kNever;
  for (const Channel& c : ch_) {
    const uint64_t div = divider(c);
    if (!c.running || div == 0) continue;
    if ((c.imr & kCpcs) && c.rc != 0 && rcTrigger(c)) {
      const uint64_t next = c.start + (compares(c) + 1) * c.rc * div;
      if (next < t) t = next;
    }
    if ((c.imr & kCovfs) && !(rcTrigger(c) && c.rc != 0)) {
      const uint64_t next = c.start + (overflows(c) + 1) * 65536 * div;
      if (next < t) t = next;
    }
  }
  return t;
}

void TimerCounter::restart(Channel& c) {
  c.start = clock_.now;
  c.comparesRead = 0;
  c.overflowsRead = 0;
}

void TimerCounter::capture(Channel& c, bool rising) {
  if ((c.cmr & kWave) || !c.running) return;
  const bool hadRa = c.raLoaded;
  if (edgeSelected((c.cmr >> 16) & 3, rising)) {
    if (c.raUnread) c.latched |= kLovrs;
    c.ra = counter(c);
    c.raUnread = c.raLoaded = true;
    c.latched |= kLdras;
  }
  if (edgeSelected((c.cmr >> 18) & 3, rising) && hadRa) {
    if (c.rbUnread) c.latched |= kLovrs;
    c.rb = counter(c);
    c.rbUnread = true;
    c.raLoaded = false;
    c.latched |= kLdrbs;
    if (c.cmr & (kLdbstop | kLdbdis)) c.running = false;  // the clock stops (LDBDIS: and is disabled)
  }
  if ((c.cmr & kAbetrg) && edgeSelected((c.cmr >> 8) & 3, rising) && c.running) {
    c.latched |= kEtrgs;
    c.raLoaded = false;
    restart(c);
  }
  clock_.poke();
}

void TimerCounter::setTioa(int i, bool level) {
  Channel& c = ch_[static_cast<size_t>(i)];
  if (level == c.tioa) return;
  c.tioa = level;
  capture(c, level);
}

void TimerCounter::pinsChanged(uint32_t levels) {
  for (int i = 0; i < 3; ++i) setTioa(i, ((levels >> kTioaPin[static_cast<size_t>(i)]) & 1u) != 0);
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
    case 0x14:
      v = c.ra;
      c.raUnread = false;
      return true;
    case 0x18:
      v = c.rb;
      c.rbUnread = false;
      return true;
    case 0x1C: v = c.rc; return true;
    case 0x20:
      v = status(c);
      c.comparesRead = compares(c);
      c.overflowsRead = overflows(c);
      c.latched &= ~kLatchedBits;
      return true;
    case 0x2C: v = c.imr; return true;
    default: return false;
  }
}

bool TimerCounter::write(uint32_t off, uint32_t v) {
  if (off >= 0xC0) return off == 0xC0 || off == 0xC4;  // BCR (SYNC) / BMR: accepted
  Channel& c = ch_[off / 0x40];
  const bool wave = (c.cmr & kWave) != 0;
  switch (off % 0x40) {
    case 0x00:
      if (v & 2) c.running = false;  // CLKDIS wins over CLKEN
      if ((v & 1) && !(v & 2) && !c.running) {
        c.running = true;
        restart(c);
      }
      if ((v & 4) && c.running) {  // SWTRG: restart at 0
        c.raLoaded = false;
        restart(c);
      }
      return true;
    case 0x04: c.cmr = v; return true;
    case 0x14:  // RA and RB are read-only in capture mode
      if (wave) c.ra = v & 0xFFFF;
      return true;
    case 0x18:
      if (wave) c.rb = v & 0xFFFF;
      return true;
    case 0x1C: c.rc = v & 0xFFFF; return true;
    case 0x24: c.imr |= v & 0xFF; return true;
    case 0x28: c.imr &= ~v; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
