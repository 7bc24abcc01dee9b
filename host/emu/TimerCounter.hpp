// TimerCounter: the TC block (0xFFFA0000, channels 0..2 at +0x40 each, IDs 12..14). Counting from
// MCK/2../1024, RC compare (CPCS) with the RC trigger (capture CPCTRG or waveform WAVSEL=10) restarting
// the count; status read clears; the counter value is computed from the clock. Used as the bit-clock tick
// of the soft I2C driver. External triggers and capture inputs are not modelled.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>

namespace nxtmap::emu {

class TimerCounter : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFA0000;
  static constexpr uint32_t kSize = 0x100;
  explicit TimerCounter(Clock& clock) : clock_(clock) {}

  const char* name() const override { return "TC"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  bool writeReplans(uint32_t off) const override {
    const uint32_t r = off % 0x40;
    return off >= 0xC0 || (r != 0x04 && r != 0x14 && r != 0x18);
  }
  uint64_t nextEventAt() const override;
  bool irqLine(int channel) const;

 private:
  struct Channel {
    uint32_t cmr = 0, ra = 0, rb = 0, rc = 0, imr = 0;
    bool running = false;
    uint64_t start = 0;         // clock when the count last restarted from 0
    uint64_t comparesRead = 0;  // RC compares already reported by an SR read
  };
  uint64_t divider(const Channel& c) const;
  bool rcTrigger(const Channel& c) const;
  uint64_t compares(const Channel& c) const;  // RC compares since start
  uint32_t counter(const Channel& c) const;

  Clock& clock_;
  std::array<Channel, 3> ch_{};
};

}  // namespace nxtmap::emu
