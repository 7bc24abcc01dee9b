#pragma once
#include <cstdint>

namespace nxtmap::fw {

// Bit-banged I2C master for the NXT sensor ports, one pin action per tick (a bit takes 3 ticks:
// set SDA with SCL low, SCL high, sample and SCL low). Driven from a timer interrupt at 3x the bit
// rate. A transaction writes [address<<1, bytes...]; when it also reads, it uses the LEGO
// ultrasonic sensor's quirk instead of a plain repeated start: STOP, one extra SCL clock, START,
// [address<<1 | 1], SCL held low for kWaitBeforeRead ticks, then the bytes (ACK each but the last,
// NACK the last), then STOP. Pure logic over a Pins object with:
//   void scl(bool high); void sdaDrive(bool high); void sdaRelease(); bool sda() const;
class SoftI2c {
 public:
  static constexpr uint8_t kMaxWrite = 4;
  static constexpr uint8_t kMaxRead = 8;
  static constexpr uint8_t kWaitBeforeRead = 5;
  enum class Result : uint8_t { Idle, Busy, Done, Nack };

  // Starts a transaction; false when one is running or the sizes are out of range.
  bool start(uint8_t address7, const uint8_t* write, uint8_t writeLen, uint8_t readLen) {
    if (result_ == Result::Busy || writeLen > kMaxWrite || readLen > kMaxRead) return false;
    out_[0] = static_cast<uint8_t>(address7 << 1);
    for (uint8_t i = 0; i < writeLen; ++i) out_[i + 1] = write[i];
    outLen_ = static_cast<uint8_t>(writeLen + 1);
    readLen_ = readLen;
    readCount_ = 0;
    outPos_ = 0;
    reading_ = false;
    nacked_ = false;
    address7_ = address7;
    phase_ = Phase::Start;
    sub_ = 0;
    result_ = Result::Busy;
    return true;
  }

  Result result() const { return result_; }
  bool busy() const { return result_ == Result::Busy; }
  const uint8_t* readData() const { return in_; }
  uint8_t readCount() const { return readCount_; }
  // Acknowledges a finished transaction (Done/Nack -> Idle).
  void release() {
    if (result_ != Result::Busy) result_ = Result::Idle;
  }

  // One tick: performs the next pin action. Does nothing when not busy.
  template <class Pins>
  void tick(Pins& p) {
    if (result_ != Result::Busy) return;
    switch (phase_) {
      case Phase::Start:  // from idle (both high): SDA falls while SCL high, then SCL low
        if (sub_ == 0) {
          p.sdaDrive(true);
          p.scl(true);
        } else if (sub_ == 1)
          p.sdaDrive(false);
        else {
          p.scl(false);
          beginByte(out_[0]);
          next(Phase::WriteBit);
          return;
        }
        ++sub_;
        return;
      case Phase::WriteBit:
        if (sub_ == 0)
          p.sdaDrive((byte_ >> bit_) & 1u);
        else if (sub_ == 1)
          p.scl(true);
        else {
          p.scl(false);
          if (bit_ == 0)
            next(Phase::AckIn);
          else {
            --bit_;
            sub_ = 0;
          }
          return;
        }
        ++sub_;
        return;
      case Phase::AckIn:
        if (sub_ == 0)
          p.sdaRelease();
        else if (sub_ == 1)
          p.scl(true);
        else {
          const bool nack = p.sda();
          p.scl(false);
          if (nack) {
            nacked_ = true;
            next(Phase::Stop);
            return;
          }
          afterByteWritten();
          return;
        }
        ++sub_;
        return;
      case Phase::
          LegoRestart:  // SDA low, SCL high, SDA high (STOP), SCL low, SCL high (extra), SDA low (START), SCL low
        switch (sub_) {
          case 0: p.sdaDrive(false); break;
          case 1: p.scl(true); break;
          case 2: p.sdaDrive(true); break;
          case 3: p.scl(false); break;
          case 4: p.scl(true); break;
          case 5: p.sdaDrive(false); break;
          default:
            p.scl(false);
            reading_ = true;
            beginByte(static_cast<uint8_t>((address7_ << 1) | 1u));
            next(Phase::WriteBit);
            return;
        }
        ++sub_;
        return;
      case Phase::WaitBeforeRead:
        if (sub_ == 0) p.sdaRelease();
        if (++sub_ >= kWaitBeforeRead) {
          beginByte(0);
          next(Phase::ReadBit);
        }
        return;
      case Phase::ReadBit:
        if (sub_ == 0)
          p.sdaRelease();
        else if (sub_ == 1)
          p.scl(true);
        else {
          byte_ = static_cast<uint8_t>((byte_ << 1) | (p.sda() ? 1u : 0u));
          p.scl(false);
          if (bit_ == 0) {
            in_[readCount_++] = byte_;
            next(Phase::AckOut);
          } else {
            --bit_;
            sub_ = 0;
          }
          return;
        }
        ++sub_;
        return;
      case Phase::AckOut:  // ACK (SDA low) all but the last byte
        if (sub_ == 0)
          p.sdaDrive(readCount_ >= readLen_);
        else if (sub_ == 1)
          p.scl(true);
        else {
          p.scl(false);
          if (readCount_ >= readLen_)
            next(Phase::Stop);
          else {
            beginByte(0);
            next(Phase::ReadBit);
          }
          return;
        }
        ++sub_;
        return;
      case Phase::Stop:  // SDA low with SCL low, SCL high, SDA high
        if (sub_ == 0)
          p.sdaDrive(false);
        else if (sub_ == 1)
          p.scl(true);
        else {
          p.sdaDrive(true);
          result_ = nacked_ ? Result::Nack : Result::Done;  // the bus is free again
          return;
        }
        ++sub_;
        return;
    }
  }

 private:
  enum class Phase : uint8_t { Start, WriteBit, AckIn, LegoRestart, WaitBeforeRead, ReadBit, AckOut, Stop };

  void next(Phase ph) {
    phase_ = ph;
    sub_ = 0;
  }
  void beginByte(uint8_t b) {
    byte_ = b;
    bit_ = 7;
  }
  void afterByteWritten() {
    if (reading_) {
      next(Phase::WaitBeforeRead);
      return;
    }
    if (++outPos_ < outLen_) {
      beginByte(out_[outPos_]);
      next(Phase::WriteBit);
      return;
    }
    next(readLen_ > 0 ? Phase::LegoRestart : Phase::Stop);
  }

  uint8_t out_[kMaxWrite + 1] = {};
  uint8_t in_[kMaxRead] = {};
  uint8_t outLen_ = 0, outPos_ = 0, readLen_ = 0, readCount_ = 0, address7_ = 0;
  uint8_t byte_ = 0, bit_ = 0, sub_ = 0;
  bool reading_ = false;
  bool nacked_ = false;  // a NACK ends the transaction with a STOP
  Phase phase_ = Phase::Start;
  volatile Result result_ = Result::Idle;
};

}  // namespace nxtmap::fw
