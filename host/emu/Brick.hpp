// Brick: the emulated NXT: the machine with every board peripheral model, wired to a simulated world.
// The AVR's motor power turns the simulated wheels, the four ultrasonic sensors answer from the
// simulator's sonar at the robot's pose, the BlueCore bridges stream bytes to a LinkEndpoint, the LCD
// keeps its picture. Owns all models; the world must outlive the brick.
#pragma once

#include "host/emu/Adc.hpp"
#include "host/emu/AvrModel.hpp"
#include "host/emu/BlueCore.hpp"
#include "host/emu/ButtonScript.hpp"
#include "host/emu/DriveModel.hpp"
#include "host/emu/Lcd.hpp"
#include "host/emu/Machine.hpp"
#include "host/emu/Pioa.hpp"
#include "host/emu/Pwm.hpp"
#include "host/emu/Spi.hpp"
#include "host/emu/Ssc.hpp"
#include "host/emu/TestPort.hpp"
#include "host/emu/TimerCounter.hpp"
#include "host/emu/Twi.hpp"
#include "host/emu/Udp.hpp"
#include "host/emu/UltrasonicSensor.hpp"
#include "host/emu/Usart.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/SimRobot.hpp"
#include "host/sim/Site.hpp"
#include "host/sim/World.hpp"

#include <array>
#include <memory>
#include <optional>

namespace nxtmap::emu {

struct BrickConfig {
  int startCol = 0, startRow = 0;  // start cell of the site's raster (when startPose is empty)
  sim::Heading heading = sim::Heading::N;
  std::optional<sim::StartPose> startPose;  // a start in the plane instead
  double startJitterDeg = 0.0;              // > 0: set down off the cell centre and up to this far off square
  // The robot as built (cells, body, sensor mounts); empty: a point robot of the raster's cells with its
  // sensors mountOffsetCm out. It must match the firmware's own geometry (nxtmap.elf: brick).
  std::optional<sim::RobotDescription> robot;
  sim::NoiseProfile noise;
  uint64_t seed = 1;
  DriveGeometry drive;
  double mountOffsetCm = 0.0;                 // sensors ahead of the robot's centre, cm (as the firmware's mountCm)
  std::array<int, 4> portFacing{0, 1, 2, 3};  // sensor port 1..4 -> 0 front, 1 right, 2 back, 3 left
  MachineOptions machine;
  double pressEnterAtS = -1.0;   // press Enter at this emulated second for 0.3 s (< 0: never)
  bool testPort = false;         // tests only: the TestPort device at 0xFFFE8000
  LinkEndpoint* link = nullptr;  // PC side of the Bluetooth link (may be null)
};

class Brick {
 public:
  // The site must outlive the brick (its scene is shared).
  Brick(const ElfImage& image, const sim::Site& site, const BrickConfig& config);
  Brick(const ElfImage& image, const sim::World& world, const BrickConfig& config);

  Machine& machine() { return machine_; }
  const Machine& machine() const { return machine_; }
  sim::SimRobot& robot() { return robot_; }
  const sim::SimRobot& robot() const { return robot_; }
  // Where the robot was set down: its grid (the explorer's cell (0, 0) is grid.startCol/startRow, facing
  // heading) and the truth on it.
  const sim::RobotPlacement& placement() const { return placement_; }
  const AvrModel& avr() const { return avr_; }
  AvrModel& avr() { return avr_; }
  const Lcd& lcd() const { return lcd_; }
  const DriveModel& drive() const { return drive_; }
  const BlueCore& blueCore() const { return bc4_; }
  const Twi& twi() const { return twi_; }
  const Usart& usart() const { return usart_; }
  const Pioa& pioa() const { return pioa_; }
  const Ssc& ssc() const { return ssc_; }
  const UltrasonicSensor& sensor(int port) const { return *sensors_[static_cast<size_t>(port)]; }
  TestPort* testPort() { return testPort_.get(); }

  // Runs until the emulated time reaches `seconds` (from reset), a fault, or stop() says so.
  bool runFor(double seconds, const std::function<bool()>& stop = {});
  double seconds() const { return secondsFromCycles(machine_.stats().cycles); }

 private:
  bool othersFiring(int port) const;

  sim::RobotPlacement placement_;
  sim::SimRobot robot_;
  Machine machine_;
  AvrModel avr_;
  Pioa pioa_;
  Twi twi_;
  DriveModel drive_;
  BlueCore bc4_;
  Usart usart_;
  Lcd lcd_;
  Spi spi_;
  Adc adc_;
  TimerCounter tc_;
  Pwm pwm_;
  Ssc ssc_;
  Udp udp_;
  ButtonScript buttons_;
  std::array<std::unique_ptr<UltrasonicSensor>, 4> sensors_;
  std::unique_ptr<TestPort> testPort_;
};

}  // namespace nxtmap::emu
