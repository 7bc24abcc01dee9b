#include "host/emu/Pmc.hpp"

namespace nxtmap::emu {

bool Pmc::read(uint32_t off, uint32_t& v) {
  switch (off) {
    case 0x08: v = scsr_; return true;
    case 0x18: v = pcsr_; return true;
    case 0x20: v = mor_; return true;
    case 0x24: v = (1u << 16) | 1130; return true;  // MCFR: MAINRDY, 18.432 MHz in 16 slow clocks
    case 0x2C: v = pllr_; return true;
    case 0x30: v = mckr_; return true;
    case 0x40:
    case 0x44:
    case 0x48: v = pck_[(off - 0x40) / 4]; return true;
    case 0x68: v = 0x0000070D; return true;  // SR: MOSCS, LOCK, MCKRDY, PCKRDY0..2
    case 0x6C: v = imr_; return true;
    default: return false;
  }
}

bool Pmc::write(uint32_t off, uint32_t v) {
  switch (off) {
    case 0x00: scsr_ |= v; return true;
    case 0x04:
      if (v & 1) {
        ++idles_;
        onIdle_();
      }  // processor clock off until the next interrupt
      scsr_ &= ~(v & ~1u);
      return true;
    case 0x10: pcsr_ |= v; return true;
    case 0x14: pcsr_ &= ~v; return true;
    case 0x20: mor_ = v; return true;
    case 0x2C: pllr_ = v; return true;
    case 0x30: mckr_ = v; return true;
    case 0x40:
    case 0x44:
    case 0x48: pck_[(off - 0x40) / 4] = v; return true;
    case 0x60: imr_ |= v; return true;
    case 0x64: imr_ &= ~v; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
