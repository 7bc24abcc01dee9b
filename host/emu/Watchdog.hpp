// Watchdog: WDT (0xFFFFFD40). WDMR is write-once; enabled at reset with a 16 s period. If the firmware
// neither disables nor restarts it, the watchdog reset stops the run loudly.
#pragma once

#include "host/emu/IoDevice.hpp"

namespace nxtmap::emu {

class Watchdog : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFFD40;
  static constexpr uint32_t kSize = 0x10;
  explicit Watchdog(Clock& clock) : clock_(clock) {}

  const char* name() const override { return "WDT"; }
  bool writeReplans(uint32_t off) const override { return off == 0x4; }  // a restart only moves the deadline later
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  uint64_t nextEventAt() const override;
  void advanceTo(uint64_t now) override {
    if (now >= nextEventAt()) expired_ = true;
  }
  bool expired() const { return expired_; }

 private:
  uint64_t timeoutCycles() const { return (uint64_t{(mr_ & 0xFFF)} + 1) * 128 * kMckHz / 32768; }
  Clock& clock_;
  uint32_t mr_ = 0x3FFF2FFF;
  bool written_ = false;
  uint64_t restartedAt_ = 0;
  bool expired_ = false;
};

}  // namespace nxtmap::emu
