#include "host/emu/UltrasonicSensor.hpp"

namespace nxtmap::emu {

namespace {
constexpr uint8_t kRegInterval = 0x40, kRegMode = 0x41, kRegDistance0 = 0x42;
constexpr uint8_t kModeOff = 0x00, kModeSingle = 0x01, kModeContinuous = 0x02, kModeReset = 0x04;
constexpr uint64_t kContinuousCycles = kMckHz / 1000 * 30;  // a continuous-mode measurement every 30 ms
void putString(std::array<uint8_t, 256>& r, uint8_t at, const char* s) {
  for (size_t i = 0; s[i] != '\0'; ++i) r[at + i] = static_cast<uint8_t>(s[i]);
}
}  // namespace

UltrasonicSensor::UltrasonicSensor(Clock& clock, Pioa& pio, const AvrModel& avr, sim::SimRobot& robot, int port,
                                   int facing, std::function<bool(int)> othersFiring)
    : clock_(clock),
      pio_(pio),
      avr_(avr),
      robot_(robot),
      port_(port),
      facing_(facing),
      othersFiring_(std::move(othersFiring)),
      client_(pio.addPullClient()),
      sclMask_(1u << kSclPin[static_cast<size_t>(port)]),
      sdaMask_(1u << kSdaPin[static_cast<size_t>(port)]) {
  putString(regs_, 0x00, "V1.0");
  putString(regs_, 0x08, "LEGO");
  putString(regs_, 0x10, "Sonar");
  regs_[0x12] = 0x01;
  regs_[0x13] = 0x0E;
  putString(regs_, 0x14, "10E-2m");
  regs_[kRegInterval] = 1;
  regs_[kRegMode] = kModeContinuous;  // continuous after power-up
  for (int i = 0; i < 8; ++i) regs_[kRegDistance0 + i] = 0xFF;
  pio.observe([this](uint32_t lv) { onLines(lv); });
}

void UltrasonicSensor::pull(bool low) {
  pullSda_ = low;
  pio_.pullLow(client_, low ? sdaMask_ : 0);
}

void UltrasonicSensor::onLines(uint32_t levels) {
  const bool scl = (levels & sclMask_) != 0;
  const bool sda = (levels & sdaMask_) != 0;
  const bool sclRose = scl && !scl_, sclFell = !scl && scl_;
  const bool sdaFell = !sda && sda_, sdaRose = sda && !sda_;
  scl_ = scl;
  sda_ = sda;
  if (!avr_.sensorPowered(port_)) {  // no 9 V: the sensor is dead and pulls nothing
    state_ = State::Idle;
    if (pullSda_) pull(false);
    return;
  }
  if (scl && !sclRose && !pullSda_) {
    if (sdaFell) {  // START (also a repeated start)
      state_ = State::Address;
      shift_ = 0;
      bits_ = 0;
      return;
    }
    if (sdaRose) {  // STOP
      state_ = State::Idle;
      return;
    }
  }
  if (sclRose) onSclRise(sda);
  if (sclFell) onSclFall();
}

void UltrasonicSensor::onSclRise(bool sda) {
  if (state_ == State::Address || state_ == State::Write) {
    shift_ = static_cast<uint8_t>((shift_ << 1) | (sda ? 1 : 0));
    ++bits_;
  } else if (state_ == State::ReadAck) {
    masterAck_ = !sda;
  }
}

void UltrasonicSensor::onSclFall() {
  switch (state_) {
    case State::Address:
      if (bits_ < 8) return;
      if ((shift_ >> 1) != 0x01) {
        state_ = State::Ignore;
        return;
      }
      ++acked_;
      readFrame_ = (shift_ & 1) != 0;
      state_ = State::AddrAck;
      pull(true);  // ACK during the 9th clock
      return;
    case State::Write:
      if (bits_ < 8) return;
      written(shift_);
      state_ = State::WriteAck;
      pull(true);
      return;
    case State::AddrAck:
    case State::WriteAck:
      pull(false);
      if (state_ == State::AddrAck && readFrame_) {
        out_ = readRegister(pointer_++);
        bits_ = 7;
        state_ = State::Read;
        pull(((out_ >> bits_) & 1) == 0);
        return;
      }
      if (state_ == State::AddrAck) firstData_ = true;
      state_ = State::Write;
      shift_ = 0;
      bits_ = 0;
      return;
    case State::Read:
      if (--bits_ >= 0) {
        pull(((out_ >> bits_) & 1) == 0);
      } else {
        pull(false);  // the master's ACK slot
        state_ = State::ReadAck;
      }
      return;
    case State::ReadAck:
      if (masterAck_) {
        out_ = readRegister(pointer_++);
        bits_ = 7;
        state_ = State::Read;
        pull(((out_ >> bits_) & 1) == 0);
      } else {
        state_ = State::Idle;  // NACK: the master ends with STOP
      }
      return;
    default: return;
  }
}

void UltrasonicSensor::written(uint8_t v) {
  if (firstData_) {
    pointer_ = v;
    firstData_ = false;
    return;
  }
  const uint8_t reg = pointer_++;
  if (reg == kRegMode) {
    if (v == kModeReset) {
      regs_[kRegMode] = kModeContinuous;
      return;
    }
    regs_[kRegMode] = v;
    if (v == kModeSingle) ping();
    return;
  }
  if (reg == kRegInterval || (reg >= 0x4A && reg <= 0x52)) regs_[reg] = v;
}

void UltrasonicSensor::ping() {
  const double atMs = static_cast<double>(clock_.now) * 1000.0 / static_cast<double>(kMckHz);
  const int cm = robot_.pingAt(facing_, atMs, othersFiring_ ? othersFiring_(port_) : false);
  regs_[kRegDistance0] = static_cast<uint8_t>(cm);
  for (int i = 1; i < 8; ++i) regs_[kRegDistance0 + i] = 0xFF;  // later echoes: none modelled
  lastPingAt_ = clock_.now;
  havePing_ = true;
  ++pings_;
}

uint8_t UltrasonicSensor::readRegister(uint8_t reg) {
  if (reg == kRegDistance0 && regs_[kRegMode] == kModeContinuous &&
      (!havePing_ || clock_.now - lastPingAt_ >= kContinuousCycles))
    ping();
  if (reg == kRegMode && regs_[kRegMode] == kModeOff) return kModeOff;
  return regs_[reg];
}

}  // namespace nxtmap::emu
