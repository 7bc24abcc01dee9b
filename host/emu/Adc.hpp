// Adc: the A/D converter (0xFFFD8000, ID 4), as a brick on batteries without a USB cable reads it. Channel 6
// carries the BlueCore's CMD signal (0x3FF while its stream is open, 0 otherwise); channel 4 is USB VBUS
// through a divider (0: no cable); the other channels (sensor pins 1 of ports 1-4 on channels 1, 2, 3, 7)
// read 0x3FF (pulled up, nothing plugged in). A START converts every
// enabled channel at once (conversion time not modelled).
#pragma once

#include "host/emu/IoDevice.hpp"

#include <functional>

namespace nxtmap::emu {

class Adc : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFD8000;
  static constexpr uint32_t kSize = 0x200;
  static constexpr uint32_t kUsbVbus = 4;
  explicit Adc(std::function<bool()> bc4Cmd) : bc4Cmd_(std::move(bc4Cmd)) {}
  const char* name() const override { return "ADC"; }
  bool read(uint32_t off, uint32_t& v) override {
    if (off >= 0x30 && off <= 0x4C) {
      const uint32_t ch = (off - 0x30) / 4;
      v = cdr_[ch];
      sr_ &= ~(1u << ch);
      return true;
    }
    switch (off) {
      case 0x04: v = mr_; return true;
      case 0x18: v = chsr_; return true;
      case 0x1C: v = sr_; return true;
      case 0x20:
        v = lcdr_;
        sr_ &= ~(1u << 16);
        return true;
      case 0x2C: v = imr_; return true;
      default: return false;
    }
  }
  bool write(uint32_t off, uint32_t v) override {
    switch (off) {
      case 0x00:
        if (v & 1) {
          sr_ = 0;
          chsr_ = 0;
        }
        if (v & 2) convert();
        return true;
      case 0x04: mr_ = v; return true;
      case 0x10: chsr_ |= v & 0xFF; return true;
      case 0x14: chsr_ &= ~v; return true;
      case 0x24: imr_ |= v; return true;
      case 0x28: imr_ &= ~v; return true;
      default: return false;
    }
  }
  bool irqLine() const { return (sr_ & imr_) != 0; }
  bool writeReplans(uint32_t off) const override { return off == 0x00 || off == 0x24 || off == 0x28; }

 private:
  void convert() {
    for (uint32_t ch = 0; ch < 8; ++ch) {
      if (!(chsr_ & (1u << ch))) continue;
      cdr_[ch] = ch == 6 ? (bc4Cmd_() ? 0x3FFu : 0u) : ch == kUsbVbus ? 0u : 0x3FFu;
      lcdr_ = cdr_[ch];
      sr_ |= (1u << ch) | (1u << 16);
    }
  }
  std::function<bool()> bc4Cmd_;
  uint32_t mr_ = 0, chsr_ = 0, sr_ = 0, lcdr_ = 0, imr_ = 0;
  uint32_t cdr_[8]{};
};

}  // namespace nxtmap::emu
