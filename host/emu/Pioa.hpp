// Pioa: the parallel I/O controller A (0xFFFFF400) at pin level. A pin's level is what the ARM drives
// (PIO-controlled, output-enabled; open drain when multi-drive is on), what an external model drives
// (tacho encoders), and wired-AND with external pull-downs (I2C slaves); released lines read high
// (the board's pull-ups). Level changes latch ISR bits (read clears) and raise ID 2 when enabled in IMR.
// Observers (the I2C slaves) see every change and may pull lines low in response.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <functional>
#include <vector>

namespace nxtmap::emu {

class Pioa : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFF400;
  static constexpr uint32_t kSize = 0x100;
  using Observer = std::function<void(uint32_t levels)>;

  explicit Pioa(Clock& clock) : clock_(clock) {}
  const char* name() const override { return "PIOA"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  // Level changes poke the clock themselves (update()); only the interrupt mask needs a re-plan.
  bool writeReplans(uint32_t off) const override { return off == 0x40 || off == 0x44; }

  uint32_t levels() const { return levels_; }
  bool level(int pin) const { return (levels_ >> pin) & 1u; }
  bool irqLine() const { return (isr_ & imr_) != 0; }
  uint32_t driven() const { return psr_ & osr_; }  // pins the ARM drives as PIO outputs
  uint32_t outputData() const { return odsr_; }

  // External push-pull drivers (input pins: tacho); mask selects the pins driven.
  void driveExternal(uint32_t mask, uint32_t values);
  // External open-drain pull-downs, one mask per client (clients are numbered by addPullClient).
  int addPullClient();
  void pullLow(int client, uint32_t mask);
  void observe(Observer o) { observers_.push_back(std::move(o)); }

 private:
  void update();

  Clock& clock_;
  uint32_t psr_ = 0xFFFFFFFF, osr_ = 0, ifsr_ = 0, odsr_ = 0, imr_ = 0, isr_ = 0, mdsr_ = 0;
  uint32_t puSr_ = 0, absr_ = 0, owsr_ = 0;
  uint32_t extMask_ = 0, extValues_ = 0;
  std::vector<uint32_t> pulls_;
  uint32_t levels_ = 0xFFFFFFFF;
  std::vector<Observer> observers_;
  bool updating_ = false;
};

}  // namespace nxtmap::emu
