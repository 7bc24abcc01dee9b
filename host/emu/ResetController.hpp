// ResetController: RSTC (0xFFFFFD00) and the voltage regulator mode register (0xFFFFFD60). A processor
// reset command (key 0xA5, PROCRST) ends the run with FaultKind::Reset.
#pragma once

#include "host/emu/IoDevice.hpp"

namespace nxtmap::emu {

class ResetController : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFFD00;
  static constexpr uint32_t kSize = 0x10;
  const char* name() const override { return "RSTC"; }
  bool read(uint32_t off, uint32_t& v) override {
    if (off == 0x4) {
      v = 0;
      return true;
    }  // RSR: general (power-up) reset, NRST high
    if (off == 0x8) {
      v = mr_;
      return true;
    }
    return false;
  }
  bool write(uint32_t off, uint32_t v) override {
    if ((v >> 24) != 0xA5) return off == 0x0 || off == 0x8;  // wrong key: ignored by the chip
    if (off == 0x0) {
      if (v & 1) resetRequested_ = true;
      return true;
    }
    if (off == 0x8) {
      mr_ = v & 0x00FFFFFF;
      return true;
    }
    return false;
  }
  bool resetRequested() const { return resetRequested_; }

 private:
  uint32_t mr_ = 0;
  bool resetRequested_ = false;
};

class VoltageRegulator : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFFD60;
  static constexpr uint32_t kSize = 0x4;
  const char* name() const override { return "VREG"; }
  bool writeReplans(uint32_t) const override { return false; }
  bool read(uint32_t off, uint32_t& v) override {
    if (off) return false;
    v = mr_;
    return true;
  }
  bool write(uint32_t off, uint32_t v) override {
    if (off) return false;
    mr_ = v & 1;
    return true;
  }

 private:
  uint32_t mr_ = 0;
};

}  // namespace nxtmap::emu
