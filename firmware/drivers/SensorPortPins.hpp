#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"

namespace nxtmap::fw {

// The DIGI0 (SCL) / DIGI1 (SDA) pins of the four sensor ports (PIO A): port 1 PA23/PA18,
// port 2 PA28/PA19, port 3 PA29/PA20, port 4 PA30/PA2.
struct SensorPortPinPair {
  uint32_t scl;
  uint32_t sda;
};
constexpr SensorPortPinPair kSensorPortPins[4] = {{reg::pin(23), reg::pin(18)},
                                                  {reg::pin(28), reg::pin(19)},
                                                  {reg::pin(29), reg::pin(20)},
                                                  {reg::pin(30), reg::pin(2)}};

// The SoftI2c pin interface for one sensor port over PIO A. SCL is always driven (push-pull, the
// sensor does not stretch the clock); SDA is driven for 0 and 1 (port 4's RS-485 parts pull a
// released line low, hence full drive as leJOS does) and released (input) while the sensor talks.
template <class Bus>
class SensorPortPins {
 public:
  SensorPortPins(Bus& bus, SensorPortPinPair pins) : bus_(bus), pins_(pins) {}

  // Both lines as PIO outputs, high, pull-ups off (the port has its own), multi-drive off.
  void init() {
    using namespace reg;
    const uint32_t both = pins_.scl | pins_.sda;
    bus_.write(kPioPer, both);
    bus_.write(kPioPpudr, both);
    bus_.write(kPioMddr, both);
    bus_.write(kPioSodr, both);
    bus_.write(kPioOer, both);
  }
  void scl(bool high) { bus_.write(high ? reg::kPioSodr : reg::kPioCodr, pins_.scl); }
  void sdaDrive(bool high) {
    bus_.write(high ? reg::kPioSodr : reg::kPioCodr, pins_.sda);
    bus_.write(reg::kPioOer, pins_.sda);
  }
  void sdaRelease() { bus_.write(reg::kPioOdr, pins_.sda); }
  bool sda() const { return (bus_.read(reg::kPioPdsr) & pins_.sda) != 0; }

 private:
  Bus& bus_;
  SensorPortPinPair pins_;
};

}  // namespace nxtmap::fw
