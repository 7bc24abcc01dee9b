#include "host/emu/Pioa.hpp"

namespace nxtmap::emu {

int Pioa::addPullClient() {
  pulls_.push_back(0);
  return static_cast<int>(pulls_.size()) - 1;
}

void Pioa::pullLow(int client, uint32_t mask) {
  if (pulls_[static_cast<size_t>(client)] == mask) return;
  pulls_[static_cast<size_t>(client)] = mask;
  update();
}

void Pioa::driveExternal(uint32_t mask, uint32_t values) {
  extMask_ = mask;
  extValues_ = values & mask;
  update();
}

void Pioa::update() {
  if (updating_) return;  // an observer reacting to a change: the outer loop settles it
  updating_ = true;
  for (int settle = 0; settle < 8; ++settle) {
    uint32_t pulled = 0;
    for (uint32_t p : pulls_) pulled |= p;
    const uint32_t drivenPins = psr_ & osr_;
    // Driven high only when push-pull; open drain (multi-drive) releases the line instead.
    const uint32_t drivenLow = drivenPins & ~odsr_;
    uint32_t lv = ~drivenLow & ~pulled;
    lv = (lv & ~extMask_) | extValues_;
    const uint32_t changed = lv ^ levels_;
    if (!changed) break;
    levels_ = lv;
    isr_ |= changed;
    clock_.poke();
    for (const auto& o : observers_) o(levels_);
  }
  updating_ = false;
}

bool Pioa::read(uint32_t off, uint32_t& v) {
  switch (off) {
    case 0x08: v = psr_; return true;
    case 0x18: v = osr_; return true;
    case 0x28: v = ifsr_; return true;
    case 0x38: v = odsr_; return true;
    case 0x3C: v = levels_; return true;
    case 0x48: v = imr_; return true;
    case 0x4C:
      v = isr_;
      isr_ = 0;  // the line may drop: nothing to re-plan
      return true;
    case 0x58: v = mdsr_; return true;
    case 0x68: v = puSr_; return true;
    case 0x78: v = absr_; return true;
    case 0xA8: v = owsr_; return true;
    default: return false;
  }
}

bool Pioa::write(uint32_t off, uint32_t v) {
  switch (off) {
    case 0x00: psr_ |= v; break;
    case 0x04: psr_ &= ~v; break;
    case 0x10: osr_ |= v; break;
    case 0x14: osr_ &= ~v; break;
    case 0x20: ifsr_ |= v; break;
    case 0x24: ifsr_ &= ~v; break;
    case 0x30: odsr_ |= v; break;
    case 0x34: odsr_ &= ~v; break;
    case 0x38: odsr_ = (odsr_ & ~owsr_) | (v & owsr_); break;
    case 0x40: imr_ |= v; break;
    case 0x44: imr_ &= ~v; break;
    case 0x50: mdsr_ |= v; break;
    case 0x54: mdsr_ &= ~v; break;
    case 0x60: puSr_ |= v; break;  // PPUDR: pull-up disabled (status bit set = disabled)
    case 0x64: puSr_ &= ~v; break;
    case 0x70: absr_ &= ~v; break;
    case 0x74: absr_ |= v; break;
    case 0xA0: owsr_ |= v; break;
    case 0xA4: owsr_ &= ~v; break;
    default: return false;
  }
  update();
  return true;
}

}  // namespace nxtmap::emu
