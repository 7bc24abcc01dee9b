// ButtonScript: presses the brick's orange Enter button through the AVR model for a while at a set
// emulated time (how a user starts the exploration on the real brick).
#pragma once

#include "host/emu/AvrModel.hpp"
#include "host/emu/IoDevice.hpp"

namespace nxtmap::emu {

class ButtonScript : public IoDevice {
 public:
  static constexpr uint16_t kEnterRaw = 0x7FF;  // the ladder reads +0x7FF while Enter is down
  ButtonScript(AvrModel& avr, uint64_t pressAt, uint64_t holdCycles)
      : avr_(avr), pressAt_(pressAt), releaseAt_(pressAt == kNever ? kNever : pressAt + holdCycles) {}
  const char* name() const override { return "buttons"; }
  bool read(uint32_t, uint32_t&) override { return false; }
  bool write(uint32_t, uint32_t) override { return false; }
  uint64_t nextEventAt() const override { return pressed_ ? releaseAt_ : (done_ ? kNever : pressAt_); }
  void advanceTo(uint64_t now) override {
    if (!pressed_ && !done_ && now >= pressAt_) {
      pressed_ = true;
      avr_.setButtons(kEnterRaw);
    }
    if (pressed_ && now >= releaseAt_) {
      pressed_ = false;
      done_ = true;
      avr_.setButtons(0);
    }
  }

 private:
  AvrModel& avr_;
  uint64_t pressAt_, releaseAt_;
  bool pressed_ = false, done_ = false;
};

}  // namespace nxtmap::emu
