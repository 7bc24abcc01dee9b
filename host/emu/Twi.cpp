#include "host/emu/Twi.hpp"

namespace nxtmap::emu {

uint64_t Twi::byteCycles() const {
  // SCL low + high periods: ((CLDIV or CHDIV) * 2^CKDIV + 3) MCK cycles each (SAM7S datasheet formula).
  const uint64_t ck = (cwgr_ >> 16) & 7;
  const uint64_t lo = ((cwgr_ & 0xFF) << ck) + 3;
  const uint64_t hi = (((cwgr_ >> 8) & 0xFF) << ck) + 3;
  return 9 * (lo + hi);
}

void Twi::reset() {
  mmr_ = iadr_ = cwgr_ = imr_ = rhr_ = 0;
  sr_ = kTxcomp | kTxrdy;
  enabled_ = inFrame_ = reading_ = stopAsked_ = thrFull_ = dataOnWire_ = false;
  busyUntil_ = kNever;
  frame_.clear();
}

void Twi::startByte() { busyUntil_ = clock_.now + byteCycles(); }

// START and the address byte go out now; THR's byte, if any, follows it.
void Twi::startWriteFrame() {
  inFrame_ = true;
  reading_ = false;
  dataOnWire_ = false;
  frame_.clear();
  sr_ &= ~kTxcomp;
  startByte();
}

void Twi::endFrame() {
  if (!reading_ && (mmr_ >> 16 & 0x7F) == AvrModel::kAddress) avr_.receive(frame_);
  inFrame_ = false;
  stopAsked_ = false;
  dataOnWire_ = false;
  busyUntil_ = kNever;
  sr_ |= kTxcomp | kTxrdy;
  ++frames_;
  frame_.clear();
}

void Twi::advanceTo(uint64_t now) {
  while (busyUntil_ != kNever && now >= busyUntil_) {
    const bool ack = ((mmr_ >> 16) & 0x7F) == AvrModel::kAddress;
    if (!ack) {  // address NACKed: the frame ends at once
      sr_ |= kNack;
      endFrame();
      break;
    }
    if (reading_) {
      if (sr_ & kRxrdy) sr_ |= kOvre;
      rhr_ = readIndex_ < reply_.size() ? reply_[readIndex_] : 0xFF;
      ++readIndex_;
      sr_ |= kRxrdy;
      if (stopAsked_) {
        endFrame();
        break;
      }
      busyUntil_ += byteCycles();
    } else if (dataOnWire_ && stopAsked_) {  // STOP after the data byte just sent
      const uint64_t end = busyUntil_;
      endFrame();
      if (thrFull_) {  // the byte left in THR starts the next frame
        const uint64_t saved = clock_.now;
        clock_.now = end;
        startWriteFrame();
        clock_.now = saved;
        sr_ &= ~kTxrdy;
      } else {
        break;
      }
    } else if (thrFull_) {  // THR into the shifter
      frame_.push_back(thr_);
      thrFull_ = false;
      dataOnWire_ = true;
      sr_ |= kTxrdy;
      busyUntil_ += byteCycles();
    } else {
      endFrame();  // shifter and THR empty: STOP
      break;
    }
  }
}

bool Twi::read(uint32_t off, uint32_t& v) {
  switch (off) {
    case 0x04: v = mmr_; return true;
    case 0x0C: v = iadr_; return true;
    case 0x10: v = cwgr_; return true;
    case 0x20:
      v = sr_;
      sr_ &= ~(kOvre | kNack);  // cleared on read
      return true;
    case 0x2C: v = imr_; return true;
    case 0x30:
      v = rhr_;
      sr_ &= ~kRxrdy;  // the line may drop: nothing to re-plan
      return true;
    default: return false;
  }
}

bool Twi::write(uint32_t off, uint32_t v) {
  switch (off) {
    case 0x00:
      if (v & 0x80) {
        reset();
        return true;
      }  // SWRST
      if (v & 4) enabled_ = true;
      if (v & 8) enabled_ = false;
      if ((v & 1) && enabled_ && !inFrame_ && !(mmr_ & (1u << 12))) startWriteFrame();  // START of a write frame
      if ((v & 1) && enabled_ && (mmr_ & (1u << 12))) {                                 // START of a read frame
        reading_ = true;
        inFrame_ = true;
        readIndex_ = 0;
        reply_ = avr_.reply();
        sr_ &= ~(kTxcomp | kRxrdy);
        startByte();  // address byte; the first data byte follows
        busyUntil_ += byteCycles();
      }
      if (v & 2) stopAsked_ = inFrame_;  // not kept for a later frame when no frame is open
      return true;
    case 0x04: mmr_ = v; return true;
    case 0x0C: iadr_ = v; return true;
    case 0x10: cwgr_ = v; return true;
    case 0x24: imr_ |= v; return true;
    case 0x28: imr_ &= ~v; return true;
    case 0x34:
      if (!enabled_) return true;
      thr_ = static_cast<uint8_t>(v);
      thrFull_ = true;
      sr_ &= ~kTxrdy;
      if (!inFrame_) startWriteFrame();  // the first byte starts a write frame (the address goes first)
      return true;
    default: return false;
  }
}

}  // namespace nxtmap::emu
