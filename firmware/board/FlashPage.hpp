#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"

// The brick's FlashPage::Command (board/FlashCommand.S: in RAM, interrupts held off until FRDY).
extern "C" uint32_t nxtmapFlashCommand(uint32_t fcr);

namespace nxtmap::fw {

// FlashPage: programs one 256-byte page of the brick's own flash from the running firmware (AT91SAM7S256
// EFC; LEGO's d_loader does the same for its files). The 64 words are stored at the page's addresses, which
// fills the controller's write latch (words past the caller's are all ones), then one write-page command
// erases and programs the page. A page in a locked region (64 pages, 16 KiB) is unlocked first. The command
// itself runs from RAM with interrupts held off (`Command`, board/FlashCommand.S on the brick): about 6 ms
// for a page, 6 more to unlock, during which no interrupt is served. Rated 10,000 writes per page.
template <class Bus>
class FlashPage {
 public:
  // Runs one MC_FCR command to its end; returns the MC_FSR bits seen meanwhile.
  using Command = uint32_t (*)(uint32_t fcr);
  static constexpr uint32_t kPages = 1024, kWordsPerPage = reg::kFlashPageBytes / 4;

  FlashPage(Bus& bus, Command command) : bus_(bus), command_(command) {}

  // The word at `index` (0..63) of page `page` as the flash reads now.
  uint32_t read(uint32_t page, uint32_t index) const { return bus_.read(wordAddress(page, index)); }

  // Programs page `page` (< kPages) with `words[0..n)` (n <= 64; the rest of the page all ones). True when the
  // controller reported no error and the page reads back as written; false leaves the page erased or as it was.
  bool write(uint32_t page, const uint32_t* words, uint32_t n) {
    if (page >= kPages || n > kWordsPerPage) return false;
    const uint32_t region = page / reg::kFlashPagesPerRegion;
    const uint32_t pageField = page << 8;
    if ((bus_.read(reg::kMcFsr) >> (reg::kMcFsrLocksShift + region)) & 1u) {
      if (command_(reg::kMcFcrKey | pageField | reg::kMcFcrClb) & (reg::kMcFsrLocke | reg::kMcFsrProge)) return false;
    }
    for (uint32_t i = 0; i < kWordsPerPage; ++i) bus_.write(wordAddress(page, i), i < n ? words[i] : ~0u);
    if (command_(reg::kMcFcrKey | pageField | reg::kMcFcrWp) & (reg::kMcFsrLocke | reg::kMcFsrProge)) return false;
    for (uint32_t i = 0; i < n; ++i)
      if (read(page, i) != words[i]) return false;
    return true;
  }

 private:
  static uint32_t wordAddress(uint32_t page, uint32_t index) {
    return reg::kFlashBase + page * reg::kFlashPageBytes + index * 4;
  }

  Bus& bus_;
  Command command_;
};

}  // namespace nxtmap::fw
