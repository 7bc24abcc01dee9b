#include "host/emu/Pdc.hpp"

namespace nxtmap::emu {

bool Pdc::read(uint32_t off, uint32_t& v) const {
  switch (off) {
    case 0x00: v = rpr_; return true;
    case 0x04: v = rcr_; return true;
    case 0x08: v = tpr_; return true;
    case 0x0C: v = tcr_; return true;
    case 0x10: v = rnpr_; return true;
    case 0x14: v = rncr_; return true;
    case 0x18: v = tnpr_; return true;
    case 0x1C: v = tncr_; return true;
    case 0x24: v = (rxEn_ ? 1u : 0u) | (txEn_ ? 0x100u : 0u); return true;
    default: return false;
  }
}

bool Pdc::write(uint32_t off, uint32_t v) {
  switch (off) {
    case 0x00: rpr_ = v; return true;
    case 0x04: rcr_ = v & 0xFFFF; return true;
    case 0x08: tpr_ = v; return true;
    case 0x0C: tcr_ = v & 0xFFFF; return true;
    case 0x10: rnpr_ = v; return true;
    case 0x14:
      rncr_ = v & 0xFFFF;
      if (rcr_ == 0) chainRx();
      return true;
    case 0x18: tnpr_ = v; return true;
    case 0x1C:
      tncr_ = v & 0xFFFF;
      if (tcr_ == 0) chainTx();
      return true;
    case 0x20:
      if (v & 1) rxEn_ = true;
      if (v & 2) rxEn_ = false;
      if (v & 0x100) txEn_ = true;
      if (v & 0x200) txEn_ = false;
      return true;
    default: return false;
  }
}

void Pdc::chainTx() {
  if (tncr_ == 0) return;
  tpr_ = tnpr_;
  tcr_ = tncr_;
  tncr_ = 0;
}

void Pdc::chainRx() {
  if (rncr_ == 0) return;
  rpr_ = rnpr_;
  rcr_ = rncr_;
  rncr_ = 0;
}

bool Pdc::takeTx(uint8_t& b) {
  if (!mem_.readByte(tpr_, b)) return false;
  ++tpr_;
  if (--tcr_ == 0) chainTx();
  return true;
}

bool Pdc::takeTxUnit(uint32_t& v, unsigned bytes) {
  v = 0;
  for (unsigned i = 0; i < bytes; ++i) {
    uint8_t b = 0;
    if (!mem_.readByte(tpr_ + i, b)) return false;
    v |= static_cast<uint32_t>(b) << (8 * i);
  }
  tpr_ += bytes;
  if (--tcr_ == 0) chainTx();
  return true;
}

bool Pdc::putRx(uint8_t b) {
  if (!mem_.writeByte(rpr_, b)) return false;
  ++rpr_;
  if (--rcr_ == 0) chainRx();
  return true;
}

}  // namespace nxtmap::emu
