#include "host/emu/Spi.hpp"

namespace nxtmap::emu {

uint64_t Spi::byteCycles() const {
  const uint32_t pcs = (mr_ >> 16) & 0xF;
  const int cs = (pcs & 1) == 0 ? 0 : (pcs & 2) == 0 ? 1 : (pcs & 4) == 0 ? 2 : 3;
  const uint64_t scbr = (csr_[cs] >> 8) & 0xFF;
  return 8 * (scbr == 0 ? 1 : scbr);
}

uint32_t Spi::status() const {
  uint32_t s = 0;
  if (rdrf_) s |= 1;
  if (enabled_ && !tdrFull_) s |= 2;  // TDRE
  if (pdc_.endRx()) s |= 1u << 4;
  if (pdc_.endTx()) s |= 1u << 5;
  if (pdc_.rxBufferFull()) s |= 1u << 6;
  if (pdc_.txBufferEmpty()) s |= 1u << 7;
  if (enabled_ && !tdrFull_ && shiftDoneAt_ == kNever) s |= 1u << 9;  // TXEMPTY
  if (enabled_) s |= 1u << 16;                                        // SPIENS
  return s;
}

void Spi::feed() {
  if (!enabled_) return;
  if (!tdrFull_ && pdc_.txActive()) {
    uint8_t b = 0;
    if (pdc_.takeTx(b)) {
      tdr_ = b;
      tdrFull_ = true;
    } else
      dmaFault_ = true;
  }
  if (tdrFull_ && shiftDoneAt_ == kNever) {
    shifting_ = tdr_;
    tdrFull_ = false;
    shiftDoneAt_ = clock_.now + byteCycles();
    if (pdc_.txActive()) feed();
  }
}

void Spi::advanceTo(uint64_t now) {
  while (shiftDoneAt_ != kNever && now >= shiftDoneAt_) {
    lcd_.byte(pio_.level(kA0Pin), shifting_);
    rdr_ = 0;  // MISO is not connected
    rdrf_ = true;
    const uint64_t done = shiftDoneAt_;
    shiftDoneAt_ = kNever;
    const uint64_t save = clock_.now;
    clock_.now = done;
    feed();
    clock_.now = save;
  }
}

bool Spi::read(uint32_t off, uint32_t& v) {
  if (off >= 0x100) return pdc_.read(off - 0x100, v);
  switch (off) {
    case 0x04: v = mr_; return true;
    case 0x08:
      v = rdr_;
      rdrf_ = false;
      return true;
    case 0x10: v = status(); return true;
    case 0x1C: v = imr_; return true;
    case 0x30:
    case 0x34:
    case 0x38:
    case 0x3C: v = csr_[(off - 0x30) / 4]; return true;
    default: return false;
  }
}

bool Spi::write(uint32_t off, uint32_t v) {
  if (off >= 0x100) {
    if (!pdc_.write(off - 0x100, v)) return false;
    feed();
    return true;
  }
  switch (off) {
    case 0x00:
      if (v & 0x80) {
        enabled_ = false;
        tdrFull_ = false;
        shiftDoneAt_ = kNever;
        rdrf_ = false;
      }
      if (v & 1) enabled_ = true;
      if (v & 2) enabled_ = false;
      feed();
      return true;
    case 0x04: mr_ = v; return true;
    case 0x0C:
      tdr_ = static_cast<uint8_t>(v);
      tdrFull_ = true;
      feed();
      return true;
    case 0x14: imr_ |= v; return true;
    case 0x18: imr_ &= ~v; return true;
    case 0x30:
    case 0x34:
    case 0x38:
    case 0x3C: csr_[(off - 0x30) / 4] = v; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
