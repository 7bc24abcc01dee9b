// UltrasonicSensor: one LEGO ultrasonic sensor as a bit-level I2C slave (7-bit address 1) on a sensor
// port's DIGI0 = SCL / DIGI1 = SDA pins. It decodes START/STOP, address, register pointer and data from
// the pin levels (sampling SDA on SCL rising, changing its output after SCL falls), ACKs while powered
// (9 V from the AVR frame), and answers the register map of nxt-hardware.md 5.1. Distances come from the
// simulator's sonar at the robot's pose: at the single-shot command (0x41 <- 0x01), or in continuous
// mode (0x41 <- 0x02) a fresh sample per read of 0x42 once the measurement interval has passed.
#pragma once

#include "host/emu/AvrModel.hpp"
#include "host/emu/Pioa.hpp"
#include "host/sim/SimRobot.hpp"

#include <array>
#include <cstdint>
#include <functional>

namespace nxtmap::emu {

class UltrasonicSensor {
 public:
  // port 0..3 (NXT ports 1..4); facing 0 front, 1 right, 2 back, 3 left (SimRobot sensor index).
  // othersFiring(port): whether another sensor pings at the same time (cross-talk model).
  UltrasonicSensor(Clock& clock, Pioa& pio, const AvrModel& avr, sim::SimRobot& robot, int port, int facing,
                   std::function<bool(int)> othersFiring);

  static constexpr std::array<int, 4> kSclPin{23, 28, 29, 30};
  static constexpr std::array<int, 4> kSdaPin{18, 19, 20, 2};

  uint64_t pings() const { return pings_; }         // sonar samples taken
  uint64_t transactions() const { return acked_; }  // address bytes ACKed
  uint8_t mode() const { return regs_[0x41]; }
  uint64_t lastPingAt() const { return lastPingAt_; }

 private:
  enum class State { Idle, Address, AddrAck, Write, WriteAck, Read, ReadAck, Ignore };
  void onLines(uint32_t levels);
  void onSclRise(bool sda);
  void onSclFall();
  void written(uint8_t value);
  void ping();
  uint8_t readRegister(uint8_t reg);
  void pull(bool low);

  Clock& clock_;
  Pioa& pio_;
  const AvrModel& avr_;
  sim::SimRobot& robot_;
  int port_, facing_;
  std::function<bool(int)> othersFiring_;
  int client_;
  uint32_t sclMask_, sdaMask_;
  bool scl_ = true, sda_ = true;
  State state_ = State::Idle;
  uint8_t shift_ = 0;
  int bits_ = 0;            // bits received (Address/Write) or index of the bit on the line (Read)
  bool readFrame_ = false;  // address byte had R/W = 1
  bool firstData_ = false;  // next written byte is the register pointer
  uint8_t pointer_ = 0;
  uint8_t out_ = 0;       // byte being sent
  bool pullSda_ = false;  // slave output: true = pulling SDA low
  bool masterAck_ = false;
  std::array<uint8_t, 256> regs_{};
  uint64_t lastPingAt_ = 0;
  bool havePing_ = false;
  uint64_t pings_ = 0, acked_ = 0;
};

}  // namespace nxtmap::emu
