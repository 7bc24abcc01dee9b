// MemoryController: MC (0xFFFFFF00) with the remap command, the abort status, and the embedded flash
// controller's registers (FMR/FCR/FSR at 0x60..0x68, modelled by FlashController). RCB in MC_RCR toggles
// what appears at address 0 (flash mirror after reset, RAM after remap), applied at once.
#pragma once

#include "host/emu/FlashController.hpp"
#include "host/emu/IoDevice.hpp"

#include <functional>

namespace nxtmap::emu {

class MemoryController : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFFFF00;
  static constexpr uint32_t kSize = 0x100;
  MemoryController(std::function<void()> onRemapToggle, FlashController& efc)
      : onRemap_(std::move(onRemapToggle)), efc_(efc) {}
  const char* name() const override { return "MC"; }
  bool writeReplans(uint32_t off) const override { return off == 0x60 || off == 0x64; }
  bool read(uint32_t off, uint32_t& v) override {
    switch (off) {
      case 0x04:
      case 0x08: v = 0; return true;  // ASR, AASR: no abort
      case 0x60:
      case 0x68: return efc_.read(off, v);
      default: return false;
    }
  }
  bool write(uint32_t off, uint32_t v) override {
    switch (off) {
      case 0x00:
        if (v & 1) onRemap_();
        return true;
      case 0x60:
      case 0x64: return efc_.write(off, v);
      default: return false;
    }
  }

 private:
  std::function<void()> onRemap_;
  FlashController& efc_;
};

}  // namespace nxtmap::emu
