#include "host/emu/Adc.hpp"

namespace nxtmap::emu {

namespace {
constexpr uint32_t kLowres = 1u << 4;
}

uint32_t Adc::sample(uint32_t ch) const {
  if (ch == kBc4Cmd) return bc4Cmd_ && bc4Cmd_() ? 0x3FFu : 0u;
  if (ch == kUsbVbus) return 0;  // no USB cable
  const int pin = kDigi1Pin[ch];
  if (pin < 0) return 0;  // not wired
  return !pinLevel_ || pinLevel_(pin) ? 0x3FFu : 0u;
}

void Adc::convert() {
  for (uint32_t ch = 0; ch < 8; ++ch) {
    if (!(chsr_ & (1u << ch))) continue;
    if (sr_ & (1u << ch)) sr_ |= 1u << (8 + ch);  // OVREx: the last result was never read
    if (sr_ & kDrdy) sr_ |= kGovre;
    const uint32_t v = sample(ch);
    cdr_[ch] = (mr_ & kLowres) ? v >> 2 : v;
    lcdr_ = cdr_[ch];
    sr_ |= (1u << ch) | kDrdy;
  }
}

void Adc::reset() {
  mr_ = chsr_ = sr_ = lcdr_ = imr_ = 0;
  cdr_.fill(0);
}

bool Adc::read(uint32_t off, uint32_t& v) {
  if (off >= 0x30 && off <= 0x4C) {
    const uint32_t ch = (off - 0x30) / 4;
    v = cdr_[ch];
    sr_ &= ~(1u << ch);
    return true;
  }
  switch (off) {
    case 0x04: v = mr_; return true;
    case 0x18: v = chsr_; return true;
    case 0x1C:
      v = sr_;
      sr_ &= ~(0xFF00u | kGovre);  // OVREx and GOVRE clear on read
      return true;
    case 0x20:
      v = lcdr_;
      sr_ &= ~kDrdy;
      return true;
    case 0x2C: v = imr_; return true;
    default: return false;
  }
}

bool Adc::write(uint32_t off, uint32_t v) {
  switch (off) {
    case 0x00:
      if (v & 1) reset();
      if (v & 2) convert();
      return true;
    case 0x04: mr_ = v & 0x0F1F3F3F; return true;
    case 0x10: chsr_ |= v & 0xFF; return true;
    case 0x14: chsr_ &= ~v; return true;
    case 0x24: imr_ |= v & 0xFFFFF; return true;
    case 0x28: imr_ &= ~v; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
