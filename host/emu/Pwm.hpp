// Pwm: the PWM controller (0xFFFCC000, ID 10): MR (clocks A and B: DIVA/PREA, DIVB/PREB), ENA/DIS/SR,
// IER/IDR/IMR, ISR (a channel's bit is set at the end of each of its periods, cleared when ISR is read),
// and four channels at 0x200 + 0x20 * n: CMR (CPRE 0..10 = MCK / 2^CPRE, 11 = clock A, 12 = clock B; CALG
// centre-aligned doubles the period), CDTY, CPRD, CCNT (read), CUPD (write: the new duty or period takes
// effect at the next period end, as CMR.CPD says). No output pins are modelled: nothing on the NXT board
// listens to them; the period interrupt is what firmwares use (LEGO's bit-banged I2C tick).
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>

namespace nxtmap::emu {

class Pwm : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFCC000;
  static constexpr uint32_t kSize = 0x300;
  explicit Pwm(Clock& clock) : clock_(clock) {}

  const char* name() const override { return "PWM"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  uint64_t nextEventAt() const override;
  void advanceTo(uint64_t now) override;
  bool irqLine() const { return (isr_ & imr_) != 0; }
  // MCK cycles per period of channel n (0: its clock is off or CPRD is 0).
  uint64_t periodCycles(int channel) const;

 private:
  struct Channel {
    uint32_t cmr = 0, cdty = 0, cprd = 0, cupd = 0;
    bool update = false;  // CUPD written, applies at the next period end
    uint64_t start = 0;   // cycle at which the current period began
  };
  uint64_t clockDivider(uint32_t cpre) const;  // MCK cycles per channel clock tick, 0 = off
  void endPeriods(int n, uint64_t now);

  Clock& clock_;
  uint32_t mr_ = 0, sr_ = 0, imr_ = 0, isr_ = 0;
  std::array<Channel, 4> ch_{};
};

}  // namespace nxtmap::emu
