#pragma once
#include <cstdint>

#include "firmware/drivers/SoftI2c.hpp"

namespace nxtmap::fw {

// Takes one raw sample from one LEGO ultrasonic sensor at a time, so the four sensors never hear
// each other's pings: write 0x41 <- 0x01 (single shot), wait kEchoMs, then read register 0x42 (the
// first echo, cm, 255 = none) with the LEGO restart. Between any two commands to a sensor at least
// kCommandGapMs pass; no command before kWarmupMs after the 9 V supply came on. A NACK or a bus
// error yields 255 (no echo) and counts an error. Pure logic over the SoftI2c engine (whose ticks
// come from the timer interrupt) and a millisecond clock.
class SonarSequencer {
 public:
  static constexpr uint8_t kAddress = 0x01;  // 7-bit (0x02 write / 0x03 read)
  static constexpr uint8_t kRegCommand = 0x41, kRegDistance0 = 0x42, kSingleShot = 0x01;
  static constexpr uint32_t kEchoMs = 50;
  static constexpr uint32_t kCommandGapMs = 5;
  static constexpr uint32_t kWarmupMs = 100;
  static constexpr uint8_t kNoEcho = 255;

  explicit SonarSequencer(SoftI2c& bus) : bus_(bus) {}

  // The sensors' 9 V came on at `nowMs`.
  void powered(uint32_t nowMs) { poweredAtMs_ = nowMs; }
  // Asks for one sample of `port` (0..3); false while another sample is running.
  bool request(uint8_t port) {
    if (step_ != Step::Idle) return false;
    port_ = port;
    ready_ = false;
    step_ = Step::Ping;
    return true;
  }
  bool busy() const { return step_ != Step::Idle; }
  bool ready() const { return ready_; }
  uint8_t port() const { return port_; }
  // The sample (cm, 255 = no echo); clears ready().
  uint8_t take() {
    ready_ = false;
    return sample_;
  }
  uint32_t errors() const { return errors_; }
  // The bus is needed for port(): the caller routes SoftI2c ticks to that port's pins.
  bool needsBus() const { return step_ == Step::PingSent || step_ == Step::ReadSent; }

  void poll(uint32_t nowMs) {
    switch (step_) {
      case Step::Idle: return;
      case Step::Ping: {
        if (nowMs - poweredAtMs_ < kWarmupMs || nowMs - lastCommandMs_ < kCommandGapMs) return;
        const uint8_t cmd[2] = {kRegCommand, kSingleShot};
        if (!bus_.start(kAddress, cmd, 2, 0)) return;
        step_ = Step::PingSent;
        return;
      }
      case Step::PingSent:
        if (bus_.busy()) return;
        lastCommandMs_ = pingMs_ = nowMs;
        if (bus_.result() != SoftI2c::Result::Done) return fail();
        bus_.release();
        step_ = Step::Echo;
        return;
      case Step::Echo: {
        if (nowMs - pingMs_ < kEchoMs) return;
        const uint8_t reg = kRegDistance0;
        if (!bus_.start(kAddress, &reg, 1, 1)) return;
        step_ = Step::ReadSent;
        return;
      }
      case Step::ReadSent:
        if (bus_.busy()) return;
        lastCommandMs_ = nowMs;
        if (bus_.result() != SoftI2c::Result::Done || bus_.readCount() != 1) return fail();
        sample_ = bus_.readData()[0];
        bus_.release();
        ready_ = true;
        step_ = Step::Idle;
        return;
    }
  }

 private:
  enum class Step : uint8_t { Idle, Ping, PingSent, Echo, ReadSent };
  void fail() {
    bus_.release();
    ++errors_;
    sample_ = kNoEcho;
    ready_ = true;
    step_ = Step::Idle;
  }

  SoftI2c& bus_;
  uint32_t poweredAtMs_ = 0, lastCommandMs_ = 0, pingMs_ = 0;
  uint32_t errors_ = 0;
  uint8_t port_ = 0, sample_ = kNoEcho;
  bool ready_ = false;
  Step step_ = Step::Idle;
};

}  // namespace nxtmap::fw
