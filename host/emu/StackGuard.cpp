#include "host/emu/StackGuard.hpp"

#include "host/emu/ElfImage.hpp"

#include <unicorn/unicorn.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace nxtmap::emu {
namespace {
void check(uc_err e, const char* what) {
  if (e != UC_ERR_OK) throw std::runtime_error(std::string("unicorn: ") + what + ": " + uc_strerror(e));
}

void mapPlain(uc_struct* uc, uint8_t* ram, uint32_t begin, uint32_t end) {
  if (end > begin) check(uc_mem_map_ptr(uc, begin, end - begin, UC_PROT_ALL, ram + (begin - kRamBase)), "map RAM");
}
}  // namespace

StackGuard::StackGuard(uint32_t low, uint32_t limit)
    : low_(std::clamp(low, kRamBase, kRamBase + kRamSize)), limit_(std::clamp(limit, kRamBase, kRamBase + kRamSize)) {
  if (limit_ <= low_) low_ = limit_ = 0;
}

void StackGuard::mapRam(uc_struct* uc, uint8_t* ram, bool pages) {
  ram_ = ram;
  lowStrip_ = lowStripEnd_ = highStrip_ = limit_;
  constexpr uint32_t kEnd = kRamBase + kRamSize;
  size_t page = 0;
  check(uc_query(uc, UC_QUERY_PAGE_SIZE, &page), "page size");
  const auto p = static_cast<uint32_t>(page);
  const uint32_t lowUp = (low_ + p - 1) / p * p, limitDown = limit_ / p * p;
  if (empty() || !pages) {
    mapPlain(uc, ram, kRamBase, kEnd);
    return;
  }
  if (limitDown <= lowUp) {  // no whole page: all of the guard is painted and checked after
    lowStrip_ = low_;
    lowStripEnd_ = limit_;
    mapPlain(uc, ram, kRamBase, kEnd);
    return;
  }
  lowStrip_ = low_;
  lowStripEnd_ = lowUp;
  highStrip_ = limitDown;
  mapPlain(uc, ram, kRamBase, lowUp);
  check(uc_mem_map_ptr(uc, lowUp, limitDown - lowUp, UC_PROT_READ | UC_PROT_EXEC, ram + (lowUp - kRamBase)),
        "map the stack guard");
  // uc_mem_map_ptr records the permissions but leaves the pages writable for translated code without a
  // memory hook; protecting them again marks them read-only, so every store takes the path that checks them.
  check(uc_mem_protect(uc, lowUp, limitDown - lowUp, UC_PROT_READ | UC_PROT_EXEC), "protect the stack guard");
  mapPlain(uc, ram, limitDown, kEnd);
}

bool StackGuard::intact(uint32_t begin, uint32_t end, uint8_t paint) const {  // runs after every slice: 8 at a time
  const uint64_t word = 0x0101010101010101ull * paint;
  uint64_t diff = 0;
  uint32_t a = begin;
  for (; a + 8 <= end; a += 8) {
    uint64_t v = 0;
    std::memcpy(&v, ram_ + (a - kRamBase), 8);
    diff |= v ^ word;
  }
  for (; a < end; ++a) diff |= ram_[a - kRamBase] ^ paint;
  return diff == 0;
}

std::optional<uint32_t> StackGuard::paintLost(uint8_t paint) const {
  if (ram_ == nullptr || (intact(highStrip_, limit_, paint) && intact(lowStrip_, lowStripEnd_, paint)))
    return std::nullopt;
  for (uint32_t a = limit_; a > highStrip_; --a)  // from the stacks down, as an overflow grows
    if (ram_[a - 1 - kRamBase] != paint) return (a - 1) & ~3u;
  for (uint32_t a = lowStrip_; a < lowStripEnd_; ++a)  // from .bss up, as an overrun grows
    if (ram_[a - kRamBase] != paint) return std::max(a & ~3u, low_);
  return std::nullopt;
}

}  // namespace nxtmap::emu
