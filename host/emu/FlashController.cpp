#include "host/emu/FlashController.hpp"

#include <cstdio>
#include <cstring>

namespace nxtmap::emu {

namespace {
constexpr uint32_t kKey = 0x5A;
constexpr uint32_t kWp = 0x1, kSlb = 0x2, kWpl = 0x3, kClb = 0x4, kEa = 0x8, kSgpb = 0xB, kCgpb = 0xD, kSsb = 0xF;
constexpr uint32_t kNebp = 1u << 7;
constexpr uint32_t kGpnvmBits = 2;  // SAM7S256: GPNVM0 (brown-out detector), GPNVM1 (brown-out reset)

std::string pageText(uint32_t page) {
  char b[48];
  std::snprintf(b, sizeof b, "page %u (0x%06x)", static_cast<unsigned>(page),
                static_cast<unsigned>(0x100000 + page * FlashController::kPageBytes));
  return b;
}
}  // namespace

FlashController::FlashController(Clock& clock, uint8_t* flash, std::function<void(uint32_t, uint32_t)> onProgrammed)
    : clock_(clock), flash_(flash), onProgrammed_(std::move(onProgrammed)) {
  latch_.fill(0xFFFFFFFFu);
}

void FlashController::misused(std::string what, uint32_t offset) {
  if (!misuse_.empty()) return;
  misuse_ = std::move(what);
  misuseOffset_ = offset;
  clock_.poke();
}

bool FlashController::read(uint32_t off, uint32_t& v) {
  switch (off) {
    case 0x60: v = fmr_; return true;
    case 0x68:
      v = fsr_ | (busy() ? 0u : kFrdy) | (security_ ? kSecurity : 0u) | (gpnvm_ << 8) | (locks_ << 16);
      fsr_ &= ~(kLocke | kProge);  // cleared on read
      return true;
    default: return false;
  }
}

bool FlashController::write(uint32_t off, uint32_t v) {
  switch (off) {
    case 0x60: fmr_ = v & 0x00FF0385u; return true;  // FRDY, LOCKE, PROGE interrupt enables, NEBP, FWS, FMCN
    case 0x64: command(v); return true;
    default: return false;
  }
}

void FlashController::latchWrite(uint32_t offset, uint32_t value, int size) {
  if (size != 4) {
    misused("a " + std::to_string(size) + "-byte write to flash (the latch takes 32-bit words only)", offset);
    return;
  }
  if (busy()) {
    misused("a write to flash while the flash controller is busy (FRDY 0)", offset);
    return;
  }
  const auto page = static_cast<int>((offset / kPageBytes) % kPages);
  if (latchPage_ >= 0 && page != latchPage_) {
    misused("a write to flash outside the page being filled, " + pageText(static_cast<uint32_t>(latchPage_)), offset);
    return;
  }
  if (latchPage_ < 0) latchedAt_ = clock_.now;
  latchPage_ = page;
  latch_[(offset >> 2) % latch_.size()] = value;
}

void FlashController::command(uint32_t v) {
  const uint32_t cmd = v & 0xF, page = (v >> 8) & 0x3FF;
  if ((v >> 24) != kKey) {
    fsr_ |= kProge;
    return;
  }
  if (busy()) {
    misused("a flash command while the flash controller is busy (FRDY 0)", page * kPageBytes);
    return;
  }
  const uint32_t region = page / kPagesPerRegion;
  uint64_t cycles = kLockCycles;
  switch (cmd) {
    case kWp:
    case kWpl:
      if (latchPage_ >= 0 && static_cast<uint32_t>(latchPage_) != page) {
        misused("a write command for " + pageText(page) + " after the latch was filled for " +
                    pageText(static_cast<uint32_t>(latchPage_)),
                page * kPageBytes);
        return;
      }
      if (locked(region)) {
        fsr_ |= kLocke;
        latchPage_ = -1;
        latchedAt_ = kNever;
        return;
      }
      cycles = kPageCycles;
      break;
    case kEa:
      if (locks_ != 0) {
        fsr_ |= kLocke;
        return;
      }
      cycles = kEraseAllCycles;
      break;
    case kSgpb:
    case kCgpb:
      if (page >= kGpnvmBits) {
        fsr_ |= kProge;
        return;
      }
      break;
    case kSlb:
    case kClb:
    case kSsb: break;
    default: fsr_ |= kProge; return;
  }
  pending_ = v;
  busyUntil_ = clock_.now + cycles;
  latchPage_ = -1;
  latchedAt_ = kNever;
}

void FlashController::finish() {
  const uint32_t cmd = pending_ & 0xF, page = (pending_ >> 8) & 0x3FF;
  const uint32_t region = page / kPagesPerRegion;
  busyUntil_ = kNever;
  switch (cmd) {
    case kWp:
    case kWpl: {
      uint8_t* p = flash_ + page * kPageBytes;
      for (uint32_t i = 0; i < kPageBytes; ++i) {
        const auto bits = static_cast<uint8_t>(latch_[i / 4] >> (8 * (i % 4)));
        p[i] = (fmr_ & kNebp) ? static_cast<uint8_t>(p[i] & bits) : bits;  // without erase: only 1 -> 0
      }
      ++pagesWritten_;
      if (cmd == kWpl) locks_ |= 1u << region;
      onProgrammed_(page * kPageBytes, kPageBytes);
      break;
    }
    case kEa:
      std::memset(flash_, 0xFF, kPages * kPageBytes);
      onProgrammed_(0, kPages * kPageBytes);
      break;
    case kSlb: locks_ |= 1u << region; break;
    case kClb: locks_ &= ~(1u << region); break;
    case kSgpb: gpnvm_ |= 1u << page; break;
    case kCgpb: gpnvm_ &= ~(1u << page); break;
    case kSsb: security_ = true; break;
    default: break;
  }
  latch_.fill(0xFFFFFFFFu);
}

uint64_t FlashController::nextEventAt() const {
  const uint64_t stray = latchedAt_ == kNever ? kNever : latchedAt_ + kStrayCycles;
  return std::min(busyUntil_, stray);
}

void FlashController::advanceTo(uint64_t now) {
  if (busyUntil_ != kNever && now >= busyUntil_) finish();
  if (latchedAt_ != kNever && now >= latchedAt_ + kStrayCycles) {
    misused("a write to flash not followed by a programming command within 10 ms",
            static_cast<uint32_t>(latchPage_) * kPageBytes);
    latchedAt_ = kNever;
  }
}

}  // namespace nxtmap::emu
