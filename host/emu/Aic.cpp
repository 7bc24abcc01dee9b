#include "host/emu/Aic.hpp"

namespace nxtmap::emu {

void Aic::connect(int id, std::function<bool()> line) { lines_.push_back(Line{id, std::move(line)}); }

void Aic::sample() {
  uint32_t level = 0;
  for (const Line& l : lines_)
    if (!(level & (1u << l.id)) && l.asserted()) level |= 1u << l.id;
  const uint32_t rising = level & ~lastLevel_;
  edgeLatch_ |= rising & edgeMask_;
  lastLevel_ = level;
}

uint32_t Aic::pendingFrom(uint32_t level) const { return soft_ | edgeLatch_ | (level & ~edgeMask_); }

uint32_t Aic::pending() {
  sample();
  return pendingFrom(lastLevel_);
}

uint32_t Aic::acknowledge(int id) {
  inService_.push_back(Level{id, static_cast<int>(smr_[static_cast<size_t>(id)] & 7)});
  isr_ = static_cast<uint32_t>(id);
  if (edge(id)) {
    edgeLatch_ &= ~(1u << id);
    soft_ &= ~(1u << id);
  }
  ++irqsTaken_;
  return svr_[static_cast<size_t>(id)];
}

int Aic::bestPending(bool fresh) {
  if (fresh) sample();
  const uint32_t p = pendingFrom(lastLevel_) & imr_ & ~1u;  // source 0 is FIQ, not routed to nIRQ
  if (p == 0) return -1;
  const int current = inService_.empty() ? -1 : inService_.back().prio;
  int best = -1;
  int bestPrio = current;
  for (int id = 1; id < 32; ++id) {
    if (!(p & (1u << id))) continue;
    const int prio = static_cast<int>(smr_[id] & 7);
    if (prio > bestPrio) {
      best = id;
      bestPrio = prio;
    }
  }
  return best;
}

bool Aic::read(uint32_t off, uint32_t& v) {
  if (off < 0x80) {
    v = smr_[off / 4];
    return true;
  }
  if (off < 0x100) {
    v = svr_[(off - 0x80) / 4];
    return true;
  }
  switch (off) {
    case 0x100: {  // IVR: the best source's vector; acknowledged now, or at the IVR write in protect mode
      const int id = bestPending(true);
      if (dcr_ & kProt) {
        protectRead_ = id;
        v = id < 0 ? spu_ : svr_[static_cast<size_t>(id)];
        return true;
      }
      v = id < 0 ? spu_ : acknowledge(id);
      return true;
    }
    case 0x104: v = spu_; return true;  // FVR: FIQ not used
    case 0x108: v = isr_; return true;
    case 0x10C: v = pending(); return true;
    case 0x110: v = imr_; return true;
    case 0x114: v = !(dcr_ & kGmsk) && bestPending(true) >= 0 ? 2u : 0u; return true;  // CISR: NIRQ b1
    case 0x134: v = spu_; return true;
    case 0x138: v = dcr_; return true;
    case 0x148: v = 0; return true;  // FFSR
    default: return false;
  }
}

bool Aic::write(uint32_t off, uint32_t v) {
  if (off < 0x80) {
    smr_[off / 4] = v & 0x67;
    const uint32_t bit = 1u << (off / 4);
    edgeMask_ = ((v >> 5) & 1) ? (edgeMask_ | bit) : (edgeMask_ & ~bit);
    return true;
  }
  if (off < 0x100) {
    svr_[(off - 0x80) / 4] = v;
    return true;
  }
  switch (off) {
    case 0x100:  // IVR write: the acknowledge in protect mode (no effect otherwise)
      if ((dcr_ & kProt) && protectRead_ >= 0) {
        acknowledge(protectRead_);
        if (clock_) clock_->poke();
      }
      protectRead_ = -1;
      return true;
    case 0x104: return true;
    case 0x120: imr_ |= v; return true;
    case 0x124: imr_ &= ~v; return true;
    case 0x128:
      soft_ &= ~v;
      edgeLatch_ &= ~v;
      return true;
    case 0x12C: soft_ |= v; return true;
    case 0x130:  // EOICR: re-plan only if a source now waits to be delivered
      if (!inService_.empty()) inService_.pop_back();
      if (clock_ && bestPending(true) >= 0) clock_->poke();
      return true;
    case 0x134: spu_ = v; return true;
    case 0x138: dcr_ = v & 3; return true;
    case 0x140:
    case 0x144: return true;  // FFER/FFDR: fast forcing unused
    default: return false;
  }
}

}  // namespace nxtmap::emu
