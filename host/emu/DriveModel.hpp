// DriveModel: the two driven wheels and the three motor encoders. Motor power from the AVR model turns
// each motor at a speed proportional to its power; the robot's wheel model (sim::WheelModel: backlash
// between motor and wheel, UMBmark's unequal diameters and track error, slip) turns the left/right motor
// rotations into ground arcs that move the simulated robot (differential drive over the actual track)
// through its continuous pose; a robot whose body would meet an obstacle does not move and its wheels
// stall. The encoders sit on the motors: they count motor degrees, whatever the wheels did. Each motor's
// encoder drives a quadrature pair of PIOA pins (pulse, dir): 1 pulse-pin edge per degree, pulse != dir
// on an edge = forward (nxt-hardware.md 4).
#pragma once

#include "host/emu/AvrModel.hpp"
#include "host/emu/IoDevice.hpp"
#include "host/emu/Pioa.hpp"
#include "host/sim/SimRobot.hpp"

#include <array>
#include <random>

namespace nxtmap::emu {

struct DriveGeometry {
  int leftMotor = 0;  // 0 = A, 1 = B, 2 = C
  int rightMotor = 1;
  double wheelDiameterCm = 5.6;    // NXT 56 x 26 tyre (informative: the robot's WheelModel rolls its own)
  double trackCm = 11.2;           // wheel centre to wheel centre, firmware MotionGeometry 112 mm (likewise)
  double degPerSecPerPercent = 8;  // motor speed: 100 % = 800 deg/s
};

class DriveModel : public IoDevice {
 public:
  static constexpr std::array<int, 3> kPulsePin{15, 26, 0};  // motors A, B, C
  static constexpr std::array<int, 3> kDirPin{1, 9, 8};

  // Wheels: robot.wheels(), from the robot's noise profile. A stretch is one move: it starts when the driven
  // motors set off from rest and lasts, whatever the controller does with their power, until both are at
  // rest again. It carries the random errors of one of the host's commands (WheelModel::newStretch): a
  // straight one (the motors set off the same way) one slip factor, a spin (opposite ways) one turn error,
  // drawn by an rng of this model's own (seeded: same seed, same run).
  DriveModel(Clock& clock, const AvrModel& avr, Pioa& pio, sim::SimRobot& robot, const DriveGeometry& g,
             uint64_t seed = 1);

  // Not on the bus: a time source only.
  const char* name() const override { return "drive"; }
  bool read(uint32_t, uint32_t&) override { return false; }
  bool write(uint32_t, uint32_t) override { return false; }
  uint64_t nextEventAt() const override;
  void advanceTo(uint64_t now) override;

  double wheelDeg(int motor) const { return deg_[static_cast<size_t>(motor)]; }
  uint64_t stalls() const { return stalls_; }    // integration steps refused by a blocked cell
  double drivenCm() const { return drivenCm_; }  // distance the robot's centre moved

 private:
  double speed(int motor) const;  // deg/s
  void publishPins();

  Clock& clock_;
  const AvrModel& avr_;
  Pioa& pio_;
  sim::SimRobot& robot_;
  DriveGeometry geo_;
  std::array<double, 3> deg_{};
  uint64_t last_ = 0;
  uint64_t stalls_ = 0;
  double drivenCm_ = 0.0;
  std::mt19937_64 rng_;
  std::array<int, 3> lastPower_{};
  bool moving_ = false;  // a stretch is under way (a driven motor has had power since both were at rest)
};

}  // namespace nxtmap::emu
