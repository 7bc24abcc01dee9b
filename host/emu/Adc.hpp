// Adc: the A/D converter (0xFFFD8000, ID 4), as a brick on batteries without a USB cable reads it:
// channel 6 carries the BlueCore's CMD signal (0x3FF while its stream is open, 0 otherwise); channel 4 is
// USB VBUS through a divider (0: no cable); channels 1, 2, 3, 7 are the DIGI1 wires of sensor ports 1-4
// (PA18, PA19, PA20, PA2), read as the pin's level (0x3FF released or driven high, 0 pulled low); channels
// 0 and 5 are not wired on the NXT and read 0. A START converts every enabled channel at once (conversion
// time not modelled). From the datasheet: LOWRES gives 8-bit results; EOCx is cleared by reading CDRx,
// DRDY by reading LCDR; a conversion that ends while EOCx (DRDY) is still set sets OVREx (GOVRE), both
// cleared by reading SR; SWRST resets every register.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>
#include <functional>

namespace nxtmap::emu {

class Adc : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFD8000;
  static constexpr uint32_t kSize = 0x200;
  static constexpr uint32_t kUsbVbus = 4, kBc4Cmd = 6;
  static constexpr std::array<int, 8> kDigi1Pin{-1, 18, 19, 20, -1, -1, -1, 2};  // PIOA pin per channel
  static constexpr uint32_t kDrdy = 1u << 16, kGovre = 1u << 17;
  using PinLevel = std::function<bool(int pin)>;
  // bc4Cmd: the BlueCore's CMD signal; pinLevel: a PIOA pin's level (empty: every pin released high).
  explicit Adc(std::function<bool()> bc4Cmd, PinLevel pinLevel = {})
      : bc4Cmd_(std::move(bc4Cmd)), pinLevel_(std::move(pinLevel)) {}
  const char* name() const override { return "ADC"; }
  bool read(uint32_t off, uint32_t& v) override;
  bool write(uint32_t off, uint32_t v) override;
  bool irqLine() const { return (sr_ & imr_) != 0; }
  bool writeReplans(uint32_t off) const override { return off == 0x00 || off == 0x24 || off == 0x28; }

 private:
  uint32_t sample(uint32_t channel) const;  // 10-bit value at the pin
  void convert();
  void reset();

  std::function<bool()> bc4Cmd_;
  PinLevel pinLevel_;
  uint32_t mr_ = 0, chsr_ = 0, sr_ = 0, lcdr_ = 0, imr_ = 0;
  std::array<uint32_t, 8> cdr_{};
};

}  // namespace nxtmap::emu
