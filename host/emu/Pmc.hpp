// Pmc: the Power Management Controller (0xFFFFFC00) with CKGR. Oscillator, PLL and master clock report
// ready at once. Writing PMC_SCDR bit 0 (PCK) stops the processor clock: the machine fast-forwards to the
// next interrupt (the chip's idle mode), so idle time costs no host time.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <functional>

namespace nxtmap::emu {

class Pmc : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFFC00;
  static constexpr uint32_t kSize = 0x100;
  explicit Pmc(std::function<void()> onIdle) : onIdle_(std::move(onIdle)) {}

  const char* name() const override { return "PMC"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  bool writeReplans(uint32_t) const override { return false; }  // idle requests poke by themselves

  uint32_t peripheralClocks() const { return pcsr_; }  // PCSR: bit n = peripheral ID n clocked
  uint64_t idleRequests() const { return idles_; }

 private:
  std::function<void()> onIdle_;
  uint32_t scsr_ = 1;  // PCK on
  uint32_t pcsr_ = 0;
  uint32_t mor_ = 0, pllr_ = 0x3F00, mckr_ = 0, imr_ = 0;
  uint32_t pck_[3]{};
  uint64_t idles_ = 0;
};

}  // namespace nxtmap::emu
