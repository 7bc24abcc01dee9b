// The brick's mode machine with the real parts it drives (explorer stack on a 16 x 16 grid, house
// commands, action runner, brick link) and, when a test runs it, a plain robot around it: two
// wheels that follow the motor command (800 deg/s at 100 %, as tests/firmware/ActionRunnerTest),
// counted by the tacho decoder through its pin edges, and four ultrasonic sensors on the soft I2C
// bus that hear no echo (an open floor).
#pragma once
#include <cstdint>
#include <optional>

#include "common/house/HouseBrick.hpp"
#include "common/motion/WheelRecord.hpp"
#include "common/house/RoomConfinement.hpp"
#include "firmware/app/ModeMachine.hpp"
#include "tests/firmware/I2cSlaveModel.hpp"

namespace nxtmap::fw::test {

constexpr TachoDecoder::Pins kRigPins[TachoDecoder::kMotors] = {
    {1u << 15, 1u << 1}, {1u << 26, 1u << 9}, {1u, 1u << 8}};

// The brick's flash page for the learnt wheels, in RAM: what it keeps and how often it was written (a save of
// what is kept already writes nothing, as FlashWheelStore).
struct RamWheelStore final : WheelStore {
  RamWheelStore() = default;
  explicit RamWheelStore(const WheelCalibration& w) : kept(w) {}
  bool load(WheelCalibration& w) const override {
    if (kept) w = *kept;
    return kept.has_value();
  }
  bool save(const WheelCalibration& w) override {
    if (kept && WheelRecord::same(*kept, w)) return true;
    kept = w;
    ++writes;
    return true;
  }
  std::optional<WheelCalibration> kept;
  int writes = 0;
};

struct Brick {
  static constexpr int16_t kCells = 16;
  static constexpr uint8_t kNoEchoCm = 255;  // what the LEGO sensor reads with nothing in range

  BrickConfig config{};
  ExplorerStorage<kCells, kCells, 128> storage{};
  ExplorerStack stack{storage.memory(), config.explorer()};
  uint8_t reach[packedBytes(kCells, kCells, 1)] = {};
  RoomConfinement confinement{reach, kCells, kCells, DoorwayLimits{4, 15, 3, 2}, stack.config().geometry.hitCells()};
  HouseBrick house{stack, confinement, PilotConfig{}};
  uint8_t shadow[packedBytes(kCells, kCells, 2)] = {};
  protocol::BrickLink link{stack.map().grid(), shadow, protocol::BrickLinkConfig{}};
  MotionController motion{};
  SoftI2c i2c{};
  SonarSequencer sonar{i2c};
  ActionRunner runner{motion, sonar, config.drive, stack.config().geometry, config.sensorPorts};
  MotorSafety safety{};
  TachoDecoder tacho{kRigPins};
  AvrCommand motors{};
  RamWheelStore wheels{};
  ModeMachine modes{stack, &house, runner, link, safety, tacho, motors, config, &wheels};

  I2cSlaveModel sensors[4] = {I2cSlaveModel{1}, I2cSlaveModel{1}, I2cSlaveModel{1}, I2cSlaveModel{1}};
  bool stalled = false;  // the wheels do not turn (an obstacle, or the robot held)
  uint32_t now = 0;      // ms

  Brick() { quiet(); }
  // A brick switched on with `stored` kept in its flash.
  explicit Brick(const WheelCalibration& stored) : wheels(stored) { quiet(); }
  void quiet() {
    sonar.powered(0);
    for (I2cSlaveModel& s : sensors) s.regs[0x42] = kNoEchoCm;
  }

  // One millisecond of the brick's main loop and of the robot around it.
  void tick() {
    tacho.tick();
    modes.drive(now);
    modes.driveMotors();
    for (int w = 0; w < 2; ++w) {
      const int8_t power = motors.pwm[w];
      if (stalled || power == 0) continue;
      acc_[w] += power * 8;
      turn(w, acc_[w] / 1000);
      acc_[w] %= 1000;
    }
    if (i2c.busy())
      for (int t = 0; t < 29; ++t) i2c.tick(sensors[sonar.port()]);
    ++now;
  }
  // Ticks until done() or limitMs have passed; true when done() held.
  template <class Done>
  bool runUntil(Done&& done, uint32_t limitMs) {
    for (uint32_t i = 0; i < limitMs; ++i) {
      if (done()) return true;
      tick();
    }
    return done();
  }

 private:
  // `counts` encoder edges of `motor` (+ forward): the pulse pin toggles, the direction pin says which way.
  void turn(int motor, int counts) {
    const TachoDecoder::Pins& p = kRigPins[motor];
    for (int i = 0; i < (counts < 0 ? -counts : counts); ++i) {
      levels_ ^= p.pulse;
      const bool pulseHigh = (levels_ & p.pulse) != 0;
      const bool dirHigh = counts > 0 ? !pulseHigh : pulseHigh;  // pulse != direction counts +1
      levels_ = dirHigh ? (levels_ | p.direction) : (levels_ & ~p.direction);
      tacho.onPinChange(levels_, p.pulse);
    }
  }

  uint32_t levels_ = 0;
  int32_t acc_[2] = {0, 0};
};

inline protocol::Command commandOf(protocol::CommandKind kind) {
  protocol::Command c;
  c.kind = kind;
  return c;
}

}  // namespace nxtmap::fw::test
