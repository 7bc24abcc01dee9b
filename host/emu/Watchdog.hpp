// Watchdog: WDT (0xFFFFFD40). WDMR is write-once; enabled at reset with a 16 s period (at 32.768 kHz).
// It counts the slow clock divided by 128: the period is (WDV + 1) x 128 / SLCK, with SLCK the brick's
// RC oscillator as drawn in Clock (22..42 kHz: WDV 64 is 195..378 ms). If the firmware neither disables
// nor restarts it in time, the watchdog reset stops the run loudly. longestGapCycles() is the longest
// time the firmware let it run without a restart so far (from WDMR's write).
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
  uint64_t longestGapCycles() const { return longestGap_; }
  uint64_t timeoutCycles() const { return (uint64_t{(mr_ & 0xFFF)} + 1) * 128 * kMckHz / clock_.slowClockHz; }

 private:
  Clock& clock_;
  uint32_t mr_ = 0x3FFF2FFF;
  bool written_ = false;
  uint64_t restartedAt_ = 0;
  bool expired_ = false;
  uint64_t longestGap_ = 0;
};

}  // namespace nxtmap::emu
