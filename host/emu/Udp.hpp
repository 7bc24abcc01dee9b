// Udp: the USB device port (0xFFFB0000, ID 11) of a brick with no USB cable: the registers a firmware sets
// up (GLB_STAT, FADDR, IER/IDR/IMR, ICR, RST_EP, CSR0..3, TXVC) keep what is written; no bus event ever comes
// (ISR stays 0, FIFOs are empty, FRM_NUM 0), as on a brick whose VBUS (ADC channel 4) reads low.
#pragma once

#include "host/emu/IoDevice.hpp"

#include <array>

namespace nxtmap::emu {

class Udp : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFB0000;
  static constexpr uint32_t kSize = 0x100;
  const char* name() const override { return "UDP"; }
  bool writeReplans(uint32_t) const override { return false; }  // no event can come
  bool read(uint32_t off, uint32_t& v) override {
    switch (off) {
      case 0x00: v = 0; return true;  // FRM_NUM: no frames
      case 0x04: v = glbStat_; return true;
      case 0x08: v = faddr_; return true;
      case 0x18: v = imr_; return true;
      case 0x1C: v = 0; return true;  // ISR: no bus activity
      case 0x28: v = rstEp_; return true;
      case 0x30:
      case 0x34:
      case 0x38:
      case 0x3C: v = csr_[(off - 0x30) / 4]; return true;
      case 0x50:
      case 0x54:
      case 0x58:
      case 0x5C: v = 0; return true;  // FDR: empty FIFO
      case 0x74: v = txvc_; return true;
      default: return false;
    }
  }
  bool write(uint32_t off, uint32_t v) override {
    switch (off) {
      case 0x04: glbStat_ = v & 0x1F; return true;
      case 0x08: faddr_ = v & 0x17F; return true;
      case 0x10: imr_ |= v; return true;
      case 0x14: imr_ &= ~v; return true;
      case 0x20: return true;  // ICR: nothing to clear
      case 0x28: rstEp_ = v & 0xF; return true;
      case 0x30:
      case 0x34:
      case 0x38:
      case 0x3C: csr_[(off - 0x30) / 4] = v & 0x8F87; return true;  // EPEDS, DIR, EPTYPE, DTGLE, control bits
      case 0x50:
      case 0x54:
      case 0x58:
      case 0x5C: return true;  // FDR: bytes into a FIFO no host ever reads
      case 0x74: txvc_ = v & 0x300; return true;
      default: return false;
    }
  }

 private:
  uint32_t glbStat_ = 0, faddr_ = 0x100, imr_ = 0, rstEp_ = 0, txvc_ = 0;
  std::array<uint32_t, 4> csr_{};
};

}  // namespace nxtmap::emu
