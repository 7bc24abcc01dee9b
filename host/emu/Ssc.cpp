#include "host/emu/Ssc.hpp"

namespace nxtmap::emu {

void Ssc::reset() {
  cmr_ = rcmr_ = rfmr_ = tcmr_ = tfmr_ = imr_ = 0;
  txEn_ = thrFull_ = false;
  wordEnd_ = kNever;
}

uint32_t Ssc::status() const {
  uint32_t s = 0;
  if (!thrFull_) s |= kTxrdy;
  if (!thrFull_ && wordEnd_ == kNever) s |= kTxempty;
  if (pdc_.endTx()) s |= kEndtx;
  if (pdc_.txBufferEmpty()) s |= kTxbufe;
  if (txEn_) s |= kTxenStatus;
  return s;
}

// Starts the next word if the line is free and there is one (THR first, then the PDC).
void Ssc::start() {
  if (wordEnd_ != kNever || !txEn_ || wordCycles() == 0) return;
  if (thrFull_) {
    thrFull_ = false;
  } else if (pdc_.txActive()) {
    uint32_t v = 0;
    if (!pdc_.takeTxUnit(v, unitBytes())) dmaFault_ = true;
  } else {
    return;
  }
  wordEnd_ = clock_.now + wordCycles();
}

uint64_t Ssc::nextEventAt() const {
  if (wordEnd_ == kNever) return kNever;
  // The current buffer's last word: ENDTX rises then (the words before it change no interrupt state).
  return wordEnd_ + (pdc_.txActive() ? uint64_t{pdc_.txCount()} * wordCycles() : 0);
}

void Ssc::advanceTo(uint64_t now) {
  while (wordEnd_ != kNever && now >= wordEnd_) {
    ++words_;
    const uint64_t end = wordEnd_;
    wordEnd_ = kNever;
    const uint64_t saved = clock_.now;
    clock_.now = end;  // the next word starts where this one ended
    start();
    clock_.now = saved;
  }
}

bool Ssc::read(uint32_t off, uint32_t& v) {
  if (off >= 0x100) return pdc_.read(off - 0x100, v);
  switch (off) {
    case 0x04: v = cmr_; return true;
    case 0x10: v = rcmr_; return true;
    case 0x14: v = rfmr_; return true;
    case 0x18: v = tcmr_; return true;
    case 0x1C: v = tfmr_; return true;
    case 0x20: v = 0; return true;  // RHR: nothing received
    case 0x40: v = status(); return true;
    case 0x4C: v = imr_; return true;
    default: return false;
  }
}

bool Ssc::write(uint32_t off, uint32_t v) {
  if (off >= 0x100) {
    if (!pdc_.write(off - 0x100, v)) return false;
    start();
    return true;
  }
  switch (off) {
    case 0x00:
      if (v & (1u << 15)) {
        reset();
        return true;
      }
      if (v & (1u << 9))
        txEn_ = false;  // TXDIS wins
      else if (v & (1u << 8))
        txEn_ = true;
      start();
      return true;
    case 0x04: cmr_ = v & 0xFFF; return true;
    case 0x10: rcmr_ = v; return true;
    case 0x14: rfmr_ = v; return true;
    case 0x18: tcmr_ = v; return true;
    case 0x1C: tfmr_ = v; return true;
    case 0x24:
      thrFull_ = true;
      start();
      return true;
    case 0x44: imr_ |= v; return true;
    case 0x48: imr_ &= ~v; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
