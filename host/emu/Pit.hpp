// Pit: the Periodic Interval Timer (0xFFFFFD30), counting MCK/16. Its state is computed from the clock on
// every access, so busy-waiting on PIIR advances with emulated time. Interrupt on the SYS line (ID 1).
#pragma once

#include "host/emu/IoDevice.hpp"

namespace nxtmap::emu {

class Pit : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFFD30;
  static constexpr uint32_t kSize = 0x10;
  explicit Pit(Clock& clock) : clock_(clock) {}

  const char* name() const override { return "PIT"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  uint64_t nextEventAt() const override;

  bool irqLine() const { return (mr_ & kItEn) && periodsUnread() > 0; }
  uint64_t periodCycles() const { return (uint64_t{mr_ & 0xFFFFF} + 1) * 16; }

 private:
  static constexpr uint32_t kEn = 1u << 24, kItEn = 1u << 25;
  uint64_t periods() const;  // whole periods since start
  uint64_t periodsUnread() const { return periods() - periodsRead_; }
  uint32_t valueRegister() const;  // PICNT | CPIV

  Clock& clock_;
  uint32_t mr_ = 0x000FFFFF;  // reset value: PIV max, disabled
  uint64_t start_ = 0;
  uint64_t periodsRead_ = 0;
  uint64_t frozenAt_ = 0;  // when PITEN was cleared (counting stops)
  bool running_ = false;
};

}  // namespace nxtmap::emu
