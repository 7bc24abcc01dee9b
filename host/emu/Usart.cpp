#include "host/emu/Usart.hpp"

#include <algorithm>

namespace nxtmap::emu {

// Asynchronous mode: baud = MCK / (8 (2 - OVER) (CD + FP / 8)), so a bit lasts (2 - OVER)(8 CD + FP) MCK
// cycles; CD = 0 stops the clock.
uint64_t Usart::bitCycles() const {
  const uint64_t cd = brgr_ & 0xFFFF, fp = (brgr_ >> 16) & 7;
  const uint64_t over = (mr_ >> 19) & 1;
  return cd == 0 ? 0 : (2 - over) * (8 * cd + fp);
}

uint32_t Usart::status() const {
  uint32_t s = 0;
  if (rxrdy_) s |= kRxrdy;
  if (txEn_ && !thrFull_) s |= kTxrdy;
  if (txEn_ && !thrFull_ && shiftDoneAt_ == kNever) s |= kTxempty;
  if (pdc_.endRx()) s |= kEndrx;
  if (pdc_.endTx()) s |= kEndtx;
  if (pdc_.rxBufferFull()) s |= kRxbuff;
  if (pdc_.txBufferEmpty()) s |= kTxbufe;
  if (ovre_) s |= kOvre;
  if (timeout_) s |= kTimeout;
  return s;
}

bool Usart::rtsHigh() const {
  const bool handshake = (mr_ & 0xF) == 2;
  return handshake && (!rxEn_ || pdc_.rxBufferFull());
}

void Usart::syncRts() {
  const bool high = rtsHigh();
  if (high == rtsToldHigh_) return;
  rtsToldHigh_ = high;
  peer_.armRts(high);
  if (!high) clock_.poke();  // the peer may start a byte now
}

bool Usart::canReceive() const { return rxEn_ && bitCycles() != 0; }

void Usart::refillThr() {
  if (!thrFull_ && txEn_ && pdc_.txActive()) {
    uint8_t b = 0;
    if (!pdc_.takeTx(b)) {
      dmaFault_ = true;
      return;
    }
    thr_ = b;
    thrFull_ = true;
  }
  if (thrFull_ && shiftDoneAt_ == kNever && bitCycles() != 0) {
    shifting_ = thr_;
    thrFull_ = false;
    shiftDoneAt_ = clock_.now + 10 * bitCycles();
    if (txEn_ && pdc_.txActive()) refillThr();
  }
}

uint64_t Usart::nextEventAt() const {
  uint64_t t = shiftDoneAt_;
  if (canReceive() && peer_.hasByteForArm())
    t = std::min(t, rxNextAt_ == kNever ? clock_.now + 10 * bitCycles() : rxNextAt_);
  if (timeoutArmed_ && rxSinceStart_ && rtor_ != 0) t = std::min(t, lastRxAt_ + rtor_ * bitCycles());
  return t;
}

void Usart::advanceTo(uint64_t now) {
  for (int guard = 0; guard < 100000; ++guard) {
    bool progressed = false;
    if (shiftDoneAt_ != kNever && now >= shiftDoneAt_) {
      peer_.fromArm(shifting_);
      ++sent_;
      const uint64_t done = shiftDoneAt_;
      shiftDoneAt_ = kNever;
      const uint64_t save = clock_.now;
      clock_.now = done;  // the next byte starts where this one ended
      refillThr();
      clock_.now = save;
      progressed = true;
    }
    if (canReceive() && peer_.hasByteForArm()) {
      if (rxNextAt_ == kNever) rxNextAt_ = clock_.now + 10 * bitCycles();
      if (now >= rxNextAt_) {
        const uint8_t b = peer_.takeByteForArm();
        ++received_;
        if (pdc_.rxActive()) {
          if (!pdc_.putRx(b)) dmaFault_ = true;
          syncRts();
        } else {
          if (rxrdy_) ovre_ = true;
          rhr_ = b;
          rxrdy_ = true;
        }
        lastRxAt_ = rxNextAt_;
        rxSinceStart_ = true;
        rxNextAt_ = peer_.hasByteForArm() ? rxNextAt_ + 10 * bitCycles() : kNever;
        progressed = true;
      }
    } else {
      rxNextAt_ = kNever;
    }
    if (timeoutArmed_ && rxSinceStart_ && rtor_ != 0 && now >= lastRxAt_ + rtor_ * bitCycles()) {
      timeout_ = true;
      timeoutArmed_ = false;
    }
    if (!progressed) break;
  }
}

bool Usart::read(uint32_t off, uint32_t& v) {
  if (off >= 0x100) return pdc_.read(off - 0x100, v);
  switch (off) {
    case 0x04: v = mr_; return true;
    case 0x10: v = imr_; return true;
    case 0x14: v = status(); return true;
    case 0x18:
      v = rhr_;
      rxrdy_ = false;
      return true;
    case 0x20: v = brgr_; return true;
    case 0x24: v = rtor_; return true;
    case 0x28: v = ttgr_; return true;
    default: return false;
  }
}

bool Usart::write(uint32_t off, uint32_t v) {
  if (off >= 0x100) {
    if (!pdc_.write(off - 0x100, v)) return false;
    refillThr();
    syncRts();
    return true;
  }
  switch (off) {
    case 0x00:
      if (v & (1u << 2)) {
        rxrdy_ = false;
        rxEn_ = false;
      }  // RSTRX
      if (v & (1u << 3)) {
        thrFull_ = false;
        shiftDoneAt_ = kNever;
        txEn_ = false;
      }  // RSTTX
      if (v & (1u << 4)) rxEn_ = true;
      if (v & (1u << 5)) rxEn_ = false;
      if (v & (1u << 6)) txEn_ = true;
      if (v & (1u << 7)) txEn_ = false;
      if (v & (1u << 8)) ovre_ = false;  // RSTSTA
      if (v & (1u << 11)) {
        timeout_ = false;
        timeoutArmed_ = true;
        rxSinceStart_ = false;
      }  // STTTO
      if (v & (1u << 15)) {
        timeout_ = false;
        timeoutArmed_ = true;
        lastRxAt_ = clock_.now;
        rxSinceStart_ = true;
      }  // RETTO
      refillThr();
      syncRts();
      return true;
    case 0x04:
      mr_ = v;
      syncRts();
      return true;
    case 0x08: imr_ |= v; return true;
    case 0x0C: imr_ &= ~v; return true;
    case 0x1C:
      if (!txEn_) return true;
      thr_ = static_cast<uint8_t>(v);
      thrFull_ = true;
      refillThr();
      return true;
    case 0x20: brgr_ = v & 0x7FFFF; return true;  // CD b0-15, FP b16-18
    case 0x24: rtor_ = v & 0xFFFF; return true;
    case 0x28: ttgr_ = v & 0xFF; return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
