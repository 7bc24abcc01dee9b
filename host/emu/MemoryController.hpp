// MemoryController: MC (0xFFFFFF00) with the remap command and the embedded flash controller registers.
// RCB in MC_RCR toggles what appears at address 0 (flash mirror after reset, RAM after remap); the machine
// applies it at the next block boundary. Flash programming commands are not modelled and stop the run.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <functional>

namespace nxtmap::emu {

class MemoryController : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFFF00;
  static constexpr uint32_t kSize = 0x100;
  explicit MemoryController(std::function<void()> onRemapToggle) : onRemap_(std::move(onRemapToggle)) {}
  const char* name() const override { return "MC"; }
  bool writeReplans(uint32_t) const override { return false; }
  bool read(uint32_t off, uint32_t& v) override {
    switch (off) {
      case 0x04:
      case 0x08: v = 0; return true;  // ASR, AASR: no abort
      case 0x60: v = fmr_; return true;
      case 0x68: v = 1; return true;  // FSR: FRDY, nothing locked, no error
      default: return false;
    }
  }
  bool write(uint32_t off, uint32_t v) override {
    switch (off) {
      case 0x00:
        if (v & 1) onRemap_();
        return true;
      case 0x60: fmr_ = v; return true;
      default: return false;  // FCR (flash commands) and others: not modelled
    }
  }

 private:
  std::function<void()> onRemap_;
  uint32_t fmr_ = 0;
};

}  // namespace nxtmap::emu
