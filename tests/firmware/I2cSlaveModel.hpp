#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace nxtmap::fw::test {

// A bit-level I2C bus with one slave, driven by the SoftI2c pin interface (scl / sdaDrive /
// sdaRelease / sda). It watches every line change like a logic analyser: START and STOP
// conditions, clock edges, bytes, ACKs, and answers as a register-file slave at `address7`.
// `trace` records the bus events ("S", "P", "W:xx", "R:xx", "A"/"N", "C" for a clock with no byte
// in progress) so tests can check the exact sequence, e.g. the LEGO quirk "P C S" before a read.
class I2cSlaveModel {
 public:
  explicit I2cSlaveModel(uint8_t address7) : address7_(address7) {}

  // SoftI2c pins interface.
  void scl(bool high) { set(high, sdaLine()); }
  void sdaDrive(bool high) {
    masterSdaDriven_ = true;
    masterSda_ = high;
    set(scl_, sdaLine());
  }
  void sdaRelease() {
    masterSdaDriven_ = false;
    set(scl_, sdaLine());
  }
  bool sda() const { return sdaLine(); }

  bool present = true;              // false: never ACKs
  bool requireLegoRestart = false;  // a read needs STOP + extra clock + START (else it NACKs)
  uint8_t regs[256] = {};
  std::vector<std::string> trace;
  std::vector<std::pair<uint8_t, uint8_t>> registerWrites;  // (register, value)
  bool sawContention = false;                               // master drove SDA high while the slave pulled it low

  bool idle() const { return scl_ && sdaLine(); }

 private:
  bool sdaLine() const {
    const bool master = masterSdaDriven_ ? masterSda_ : true;
    return master && !slaveLow_;
  }
  static std::string hex(uint8_t b) {
    const char* d = "0123456789abcdef";
    return std::string{d[b >> 4], d[b & 15]};
  }
  void set(bool sclNew, bool sdaNew) {
    if (masterSdaDriven_ && masterSda_ && slaveLow_) sawContention = true;
    const bool sclOld = scl_, sdaOld = sda_;
    scl_ = sclNew;
    sda_ = sdaNew;
    if (sclOld && sclNew && sdaOld && !sdaNew) return onStart();
    if (sclOld && sclNew && !sdaOld && sdaNew) return onStop();
    if (!sclOld && sclNew) onRise();
    if (sclOld && !sclNew) {
      onFall();
      sda_ = sdaLine();  // the slave changes SDA only while SCL is low
    }
  }
  void onStart() {
    trace.push_back("S");
    const bool afterQuirk = stopThenClock_;
    inFrame_ = true;
    bit_ = 0;
    byte_ = 0;
    first_ = true;
    reading_ = false;
    slaveLow_ = false;
    restartOk_ = afterQuirk;
    stopThenClock_ = false;
    sawStop_ = false;
  }
  void onStop() {
    trace.push_back("P");
    inFrame_ = false;
    slaveLow_ = false;
    sawStop_ = true;
    stopThenClock_ = false;
  }
  void onRise() {
    if (!inFrame_) {
      trace.push_back("C");
      if (sawStop_) stopThenClock_ = true;
      return;
    }
    if (ackSlot_) {  // ninth clock
      if (reading_ && !masterAckIsSlave_) trace.push_back(sda_ ? "N" : "A");
      return;
    }
    if (reading_) return;  // the slave drives data; nothing to sample
    byte_ = static_cast<uint8_t>((byte_ << 1) | (sda_ ? 1 : 0));
    ++bit_;
  }
  void onFall() {
    if (!inFrame_) return;
    if (ackSlot_) {  // end of the ninth clock
      ackSlot_ = false;
      slaveLow_ = false;
      if (reading_ && !masterAckIsSlave_) {
        // master ACKed: send the next byte; NACK: stop driving
        if (!sda_)
          beginSend();
        else
          sending_ = false;
      } else if (reading_ && masterAckIsSlave_) {
        masterAckIsSlave_ = false;
        beginSend();
      }
      if (sending_) driveBit();
      return;
    }
    if (reading_ && sending_) {
      if (++bit_ == 8) {
        trace.push_back("R:" + hex(out_));
        slaveLow_ = false;
        ackSlot_ = true;
        bit_ = 0;
        return;
      }
      driveBit();
      return;
    }
    if (bit_ == 8) {
      bit_ = 0;
      gotByte(byte_);
      byte_ = 0;
    }
  }
  void gotByte(uint8_t b) {
    trace.push_back("W:" + hex(b));
    bool ack = present;
    if (first_) {
      first_ = false;
      ack = ack && (b >> 1) == address7_;
      if (ack && (b & 1)) {
        if (requireLegoRestart && !restartOk_) ack = false;
        reading_ = ack;
        masterAckIsSlave_ = true;  // the next ninth clock is our address ACK
      }
      index_ = 0;
    } else if (index_ == 0) {
      reg_ = b;
      index_ = 1;
    } else {
      registerWrites.emplace_back(reg_, b);
      regs[reg_++] = b;
    }
    slaveLow_ = ack;
    ackSlot_ = true;
    trace.push_back(ack ? "A" : "N");
  }
  void beginSend() {
    sending_ = true;
    out_ = regs[reg_++];
    bit_ = 0;
  }
  void driveBit() { slaveLow_ = ((out_ >> (7 - bit_)) & 1) == 0; }

  uint8_t address7_;
  bool scl_ = true, sda_ = true;
  bool masterSdaDriven_ = false, masterSda_ = true, slaveLow_ = false;
  bool inFrame_ = false, first_ = true, reading_ = false, ackSlot_ = false;
  bool sending_ = false, masterAckIsSlave_ = false;
  bool sawStop_ = false, stopThenClock_ = false, restartOk_ = false;
  uint8_t bit_ = 0, byte_ = 0, out_ = 0, reg_ = 0, index_ = 0;
};

}  // namespace nxtmap::fw::test
