// Probe: the four ultrasonic sensors over bit-banged I2C on the port pins (LEGO restart quirk):
// power them (constant 9 V), then per port a single-shot ping (0x41 <- 0x01), 50 ms, read 0x42;
// also reads the product id at 0x08. Reports each distance.
#include "Probe.hpp"
using namespace probe;

namespace {
constexpr uint32_t kScl[4] = {1u << 23, 1u << 28, 1u << 29, 1u << 30};
constexpr uint32_t kSda[4] = {1u << 18, 1u << 19, 1u << 20, 1u << 2};

struct Port {
  uint32_t scl, sda;
  void delay() const {
    for (volatile int i = 0; i < 20; ++i) {}
  }
  void sclHi() const {
    REG(kSodr) = scl;
    delay();
  }
  void sclLo() const {
    REG(kCodr) = scl;
    delay();
  }
  void sdaHi() const {
    REG(kSodr) = sda;
    REG(kOer) = sda;
    delay();
  }
  void sdaLo() const {
    REG(kCodr) = sda;
    REG(kOer) = sda;
    delay();
  }
  void sdaRelease() const {
    REG(kOdr) = sda;
    delay();
  }
  bool sdaIn() const { return (REG(kPdsr) & sda) != 0; }
  void start() const {
    sdaHi();
    sclHi();
    sdaLo();
    sclLo();
  }
  void stop() const {
    sdaLo();
    sclHi();
    sdaHi();
  }
  bool put(uint8_t b) const {
    for (int i = 7; i >= 0; --i) {
      if ((b >> i) & 1)
        sdaHi();
      else
        sdaLo();
      sclHi();
      sclLo();
    }
    sdaRelease();
    sclHi();
    const bool ack = !sdaIn();
    sclLo();
    return ack;
  }
  uint8_t get(bool ack) const {
    sdaRelease();
    uint8_t b = 0;
    for (int i = 0; i < 8; ++i) {
      sclHi();
      b = static_cast<uint8_t>((b << 1) | (sdaIn() ? 1 : 0));
      sclLo();
    }
    if (ack)
      sdaLo();
    else
      sdaHi();
    sclHi();
    sclLo();
    sdaRelease();
    return b;
  }
  bool write(uint8_t reg, uint8_t v) const {
    start();
    bool ok = put(0x02) && put(reg) && put(v);
    stop();
    return ok;
  }
  // Register read with the LEGO restart: STOP, an extra clock, START, address|1.
  int read(uint8_t reg) const {
    start();
    if (!put(0x02) || !put(reg)) {
      stop();
      return -1;
    }
    sdaLo();
    sclHi();
    sdaHi();  // STOP
    sclLo();
    sclHi();  // extra clock
    sdaLo();
    sclLo();  // START
    if (!put(0x03)) {
      stop();
      return -1;
    }
    const uint8_t v = get(false);
    stop();
    return v;
  }
};
}  // namespace

int main() {
  REG(kWdtMr) = 1u << 15;
  pitStart();
  twiInit();
  avrHandshake();
  waitMs(2);
  avrCommand(0, 0, 0, 0, 0xF0);  // constant 9 V on all four ports
  Port ports[4];
  for (int p = 0; p < 4; ++p) {
    ports[p] = Port{kScl[p], kSda[p]};
    REG(kPer) = kScl[p] | kSda[p];
    REG(kPpudr) = kScl[p] | kSda[p];
    REG(kSodr) = kScl[p] | kSda[p];
    REG(kOer) = kScl[p] | kSda[p];
  }
  waitMs(10);
  report(static_cast<uint32_t>(ports[0].read(0x08)));  // 'L' of "LEGO"
  for (int p = 0; p < 4; ++p) {
    ports[p].write(0x41, 0x01);
    waitMs(50);
    report(static_cast<uint32_t>(ports[p].read(0x42)));
  }
  return 0;
}
