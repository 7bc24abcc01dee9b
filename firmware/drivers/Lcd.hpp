#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"
#include "firmware/board/Mmio.hpp"

namespace nxtmap::fw {

// The 100 x 64 LCD (UC1601) on SPI: PA13 MOSI, PA14 SPCK (peripheral A), PA10 = NPCS2 chip select
// (peripheral B), PA12 = A0 (PIO: low command, high data). 2 MHz, 8 bit, CPOL = 1.
// Bring-up: wait 20 ms, 0xE2 (reset), wait 20 ms. Refresh: first the whole setting string kSettings
// (as LEGO's firmware does before every refresh, so a controller upset by a glitch or a brown-out
// recovers within one refresh), then per page p (8 rows) commands 0x00 0x10 0xB0|p (column 0, page p)
// and the page's 100 bytes through the SPI PDC; one page per pump() so the main loop never waits long. Framebuffer: 8 pages x 100 columns, bit n of
// [page][x] = row 8*page + n, row 0 at the top; owned by the caller.
template <class Bus>
class Lcd {
 public:
  static constexpr int kWidth = 100, kPages = 8;
  static constexpr uint8_t kReset = 0xE2;
  // UC1601 settings: bias 1/9, power control (internal pump), all pixels normal, not inverse, scroll
  // line 0, VBIAS potentiometer 0x5A (contrast), mapping MY, temperature compensation, power control
  // (panel loading), line rate, RAM address control (column increment), multiplex 1:65, display on.
  static constexpr uint8_t kSettings[] = {0xEB, 0x2F, 0xA4, 0xA6, 0x40, 0x81, 0x5A,
                                          0xC4, 0x27, 0x29, 0xA0, 0x88, 0x23, 0xAF};
  static constexpr uint32_t kPowerMs = 20, kResetMs = 20;
  using Frame = uint8_t[kPages][kWidth];

  Lcd(Bus& bus, Frame& frame) : bus_(bus), frame_(frame) {}

  void init(uint32_t mck, uint32_t nowMs) {
    using namespace reg;
    bus_.write(kPmcPcer, (1u << kIdSpi) | (1u << kIdPioa));
    bus_.write(kPioPer, kPinLcdA0);
    bus_.write(kPioOer, kPinLcdA0);
    bus_.write(kPioCodr, kPinLcdA0);
    bus_.write(kPioPdr, kPinLcdMosi | kPinLcdSpck | kPinLcdCs);
    bus_.write(kPioAsr, kPinLcdMosi | kPinLcdSpck);
    bus_.write(kPioBsr, kPinLcdCs);
    bus_.write(kSpiCr, 1u << 7);                         // SWRST
    bus_.write(kSpiCr, 1u << 0);                         // SPIEN
    bus_.write(kSpiMr, 1u | (1u << 4) | (0xBu << 16));   // master, no mode fault, fixed NPCS2
    bus_.write(kSpiCsr2, ((mck / 2000000u) << 8) | 1u);  // 2 MHz, 8 bit, CPOL
    bus_.write(kSpiPtcr, 1u << 9);                       // TXTDIS
    state_ = State::PowerWait;
    sinceMs_ = nowMs;
  }

  bool ready() const { return state_ == State::Ready; }
  // Asks for the whole frame to be sent again (from page 0).
  void refresh() { dirty_ = true; }

  // Main loop: advances bring-up, or sends the next page of a pending refresh.
  void pump(uint32_t nowMs) {
    switch (state_) {
      case State::Off: return;
      case State::PowerWait:
        if (nowMs - sinceMs_ < kPowerMs) return;
        command(&kReset, 1);
        state_ = State::ResetWait;
        sinceMs_ = nowMs;
        return;
      case State::ResetWait:
        if (nowMs - sinceMs_ < kResetMs) return;
        state_ = State::Ready;
        dirty_ = true;
        return;
      case State::Ready: break;
    }
    if (!idle()) return;
    if (page_ == 0 && !dirty_) return;
    if (page_ == 0) {
      dirty_ = false;
      command(kSettings, sizeof(kSettings));
    }
    const uint8_t cmds[3] = {0x00, 0x10, static_cast<uint8_t>(0xB0 | page_)};
    command(cmds, 3);
    bus_.write(reg::kPioSodr, reg::kPinLcdA0);  // data
    compilerBarrier();                          // the page's pixels in RAM before the PDC sends them
    bus_.write(reg::kSpiTpr, bus_.address(&frame_[page_][0]));
    bus_.write(reg::kSpiTcr, kWidth);
    bus_.write(reg::kSpiPtcr, 1u << 8);  // TXTEN
    page_ = static_cast<uint8_t>((page_ + 1) % kPages);
  }
  // Sends the controller reset (before power-off: drains the charge pump). Blocking, ~20 ms by caller.
  void shutdown() { command(&kReset, 1); }

 private:
  enum class State : uint8_t { Off, PowerWait, ResetWait, Ready };

  // The SPI has sent everything (PDC done and shift register empty).
  bool idle() const { return bus_.read(reg::kSpiTcr) == 0 && (bus_.read(reg::kSpiSr) & reg::kSpiSrTxempty); }
  void waitIdle() const {
    for (uint32_t i = 0; i < 100000 && !idle(); ++i) {}
  }
  // Command bytes with A0 low, polled (a few bytes at 2 MHz).
  void command(const uint8_t* bytes, uint8_t n) {
    waitIdle();
    bus_.write(reg::kPioCodr, reg::kPinLcdA0);
    for (uint8_t i = 0; i < n; ++i) {
      for (uint32_t k = 0; k < 100000 && !(bus_.read(reg::kSpiSr) & reg::kSpiSrTdre); ++k) {}
      bus_.write(reg::kSpiTdr, bytes[i]);
    }
    waitIdle();
  }

  Bus& bus_;
  Frame& frame_;
  State state_ = State::Off;
  uint32_t sinceMs_ = 0;
  uint8_t page_ = 0;
  bool dirty_ = false;
};

}  // namespace nxtmap::fw
