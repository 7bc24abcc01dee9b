#pragma once
#include <cstdint>

namespace nxtmap::fw {

// Half-decoding of the NXT motor encoders: every edge of a motor's pulse pin counts one degree
// (360 counts per motor shaft turn); the direction pin decides the sign (pulse level != direction
// level -> +1, i.e. forward = positive power). Pure logic: feed it the PIO pin levels and the set of
// pins that changed (PIO_ISR). An edge storm (more than kMaxEdgesPerMs on one motor within one
// millisecond: noise or a loose cable) latches a fault.
class TachoDecoder {
 public:
  static constexpr int kMotors = 3;
  static constexpr uint8_t kMaxEdgesPerMs = 8;  // 8 deg/ms = 22 turns/s, far above the motor's ~2.5

  struct Pins {
    uint32_t pulse;
    uint32_t direction;
  };

  explicit TachoDecoder(const Pins (&pins)[kMotors]) {
    for (int m = 0; m < kMotors; ++m) pins_[m] = pins[m];
  }

  // Pulse pins to enable for pin-change interrupts.
  uint32_t pulseMask() const { return pins_[0].pulse | pins_[1].pulse | pins_[2].pulse; }
  uint32_t allPins() const { return pulseMask() | pins_[0].direction | pins_[1].direction | pins_[2].direction; }

  // Pin-change interrupt: `levels` = PIO_PDSR, `changed` = PIO_ISR.
  void onPinChange(uint32_t levels, uint32_t changed) {
    for (int m = 0; m < kMotors; ++m) {
      if (!(changed & pins_[m].pulse)) continue;
      const bool pulse = (levels & pins_[m].pulse) != 0;
      const bool dir = (levels & pins_[m].direction) != 0;
      count_[m] += (pulse != dir) ? 1 : -1;
      if (++edgesThisMs_[m] > kMaxEdgesPerMs) fault_ = true;
    }
  }
  // 1 ms tick: opens a new storm window.
  void tick() {
    for (int m = 0; m < kMotors; ++m) edgesThisMs_[m] = 0;
  }

  int32_t count(int motor) const { return count_[motor]; }
  bool fault() const { return fault_; }
  void clearFault() { fault_ = false; }

 private:
  Pins pins_[kMotors] = {};
  volatile int32_t count_[kMotors] = {0, 0, 0};
  uint8_t edgesThisMs_[kMotors] = {0, 0, 0};
  volatile bool fault_ = false;
};

}  // namespace nxtmap::fw
