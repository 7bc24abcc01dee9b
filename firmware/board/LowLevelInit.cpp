// Clocks, flash wait states, reset controller and watchdog: the first C++ the reset handler calls,
// before .data and .bss exist (so it uses no variables). Sequence: nxt-hardware facts section 1.4.
#include "firmware/board/At91sam7s.hpp"
#include "firmware/board/Mmio.hpp"

using nxtmap::fw::Mmio;
namespace reg = nxtmap::fw::reg;

namespace {
void waitFor(uint32_t bits) {
  for (uint32_t i = 0; i < 1000000 && (Mmio::read(reg::kPmcSr) & bits) == 0; ++i) {}
}
}  // namespace

extern "C" void nxtmapLowLevelInit() {
  Mmio::write(reg::kMcFmr, (72u << 16) | (1u << 8));  // FMCN for 48 MHz, 1 wait state
  // Watchdog (write-once): WDV = 64 at SLCK/128, reset on expiry, halted in debug. SLCK is the RC
  // oscillator, 22..42 kHz: the period is 195..378 ms (250 ms only at the nominal 32.768 kHz). The
  // system tick restarts it every 1 ms; the longest gap, boot to the first tick, is about 4 ms.
  Mmio::write(reg::kWdtMr, 64u | (0xFFFu << 16) | (1u << 13) | (1u << 28));
  Mmio::write(reg::kRstcRmr, 0xA5000401u);  // user reset enabled, 2^(4+1) slow clocks pulse
  Mmio::write(reg::kCkgrMor, 0x00000601u);  // main oscillator, 6 x 8 slow clocks start-up
  waitFor(reg::kPmcSrMoscs);
  Mmio::write(reg::kCkgrPllr, 0x10481C0Eu);  // x73 / 14 = 96.11 MHz, USB /2
  waitFor(reg::kPmcSrLock);
  waitFor(reg::kPmcSrMckrdy);
  Mmio::write(reg::kPmcMckr, 0x4u);  // prescaler /2 first
  waitFor(reg::kPmcSrMckrdy);
  Mmio::write(reg::kPmcMckr, 0x7u);  // then the PLL as source
  waitFor(reg::kPmcSrMckrdy);
}
