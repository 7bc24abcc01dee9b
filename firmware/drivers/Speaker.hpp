#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"
#include "firmware/board/Mmio.hpp"

namespace nxtmap::fw {

// The SSC (0xFFFD4000, ID 8) and its PDC as the NXT's speaker uses them: the transmit data line
// TD (PA17, peripheral A) drives the amplifier; its density of ones is the membrane's position.
// Not in board/At91sam7s.hpp yet, so named here.
namespace ssc {
constexpr uint32_t kId = 8;
constexpr uint32_t kCr = 0xFFFD4000, kCmr = 0xFFFD4004, kTcmr = 0xFFFD4018, kTfmr = 0xFFFD401C, kSr = 0xFFFD4040,
                   kIer = 0xFFFD4044, kIdr = 0xFFFD4048;
constexpr uint32_t kTpr = 0xFFFD4108, kTcr = 0xFFFD410C, kTnpr = 0xFFFD4118, kTncr = 0xFFFD411C, kPtcr = 0xFFFD4120;
constexpr uint32_t kCrTxen = 1u << 8, kCrTxdis = 1u << 9, kCrSwrst = 1u << 15;
constexpr uint32_t kSrEndtx = 1u << 2, kSrTxbufe = 1u << 3;
constexpr uint32_t kPtcrTxten = 1u << 8, kPtcrTxtdis = 1u << 9;
// TCMR: bit clock from the divider (CKS 0), clock out continuous (CKO 1), start continuous (START 0).
constexpr uint32_t kTcmrDivContinuous = 1u << 2;
// TFMR: 32-bit words (DATLEN 31), most significant bit first (MSBF).
constexpr uint32_t kTfmrWords32Msbf = 31u | (1u << 7);
constexpr uint32_t kPinTd = 1u << 17;
}  // namespace ssc

// Tones on the NXT's speaker, as LEGO's firmware makes them (facts from its d_sound.r): one period
// of the tone is 16 words of 32 bits (512 bit times), so the bit clock is 512 x the frequency,
// CMR.DIV ~ MCK / (2 x 512 x Hz); the PDC sends the period's words back to back and the
// end-of-buffer interrupt queues the next ones until the duration's periods are sent. The wave is
// our own: a square wave a quarter of full scale either side of the centre (bytes of 6 and of 2
// ones in 8). Limits as LEGO's: 220..14080 Hz, at least 10 ms; 0 Hz is silence for the duration.
//
// init() once; play()/stop() from the main loop; onInterrupt() from the SSC's interrupt (level,
// ENDTX while periods are left to queue, TXBUFE for the last). Bus: read, write, address.
template <class Bus>
class Speaker {
 public:
  static constexpr uint16_t kMinHz = 220, kMaxHz = 14080, kMinMs = 10;
  static constexpr uint32_t kWordsPerPeriod = 16, kBitsPerPeriod = kWordsPerPeriod * 32;
  static constexpr uint32_t kPeriodsPerBuffer = 2;  // one interrupt per 2 periods (<= 7,040 a second)
  static constexpr uint32_t kHigh = 0xFCFCFCFCu, kLow = 0xC0C0C0C0u;

  explicit Speaker(Bus& bus) : bus_(bus) {}

  void init() {
    for (uint32_t i = 0; i < kPeriodsPerBuffer * kWordsPerPeriod; ++i)
      wave_[i] = (i % kWordsPerPeriod) < kWordsPerPeriod / 2 ? kHigh : kLow;
    bus_.write(reg::kPmcPcer, reg::peripheralBit(ssc::kId));
    silence();
    bus_.write(reg::kPioOdr, ssc::kPinTd);
    bus_.write(reg::kPioPpudr, ssc::kPinTd);
    bus_.write(reg::kPioAsr, ssc::kPinTd);
    bus_.write(ssc::kCr, ssc::kCrSwrst);
    bus_.write(ssc::kTcmr, ssc::kTcmrDivContinuous);
    bus_.write(ssc::kTfmr, ssc::kTfmrWords32Msbf);
    bus_.write(ssc::kCr, ssc::kCrTxen);
  }

  // The SSC clock divider for `hz` (clamped to kMinHz..kMaxHz): the nearest to MCK / (2 x 512 x Hz).
  // (LEGO's truncates and adds 1, so its tones are up to one divider step flat.) The tone is then
  // MCK / (1024 x DIV): within half a step, 1 / (2 x DIV), of `hz` (0.05 % at 220 Hz, 3 % at 3 kHz).
  static uint32_t divider(uint32_t mck, uint16_t hz) {
    const uint32_t step = 2 * kBitsPerPeriod * clampHz(hz);
    return (mck + step / 2) / step;
  }
  static uint16_t clampHz(uint16_t hz) { return hz < kMinHz ? kMinHz : hz > kMaxHz ? kMaxHz : hz; }

  // Plays `hz` for `ms` (replacing a tone playing now).
  void play(uint32_t mck, uint16_t hz, uint16_t ms) {
    stop();
    const uint32_t duration = ms < kMinMs ? kMinMs : ms;
    const uint32_t f = hz == 0 ? 1000 : clampHz(hz);
    left_ = f * duration / 1000;
    bus_.write(ssc::kCmr, divider(mck, static_cast<uint16_t>(f)));
    compilerBarrier();  // the wave in RAM before the PDC sends it
    bus_.write(ssc::kTpr, bus_.address(wave_));
    bus_.write(ssc::kTcr, take());
    if (left_ > 0) queueNext();
    bus_.write(ssc::kPtcr, ssc::kPtcrTxten);
    if (hz != 0) bus_.write(reg::kPioPdr, ssc::kPinTd);  // TD drives the amplifier
    playing_ = true;
    bus_.write(ssc::kIer, left_ > 0 ? ssc::kSrEndtx : ssc::kSrTxbufe);
  }

  // Silence now: the words queued are dropped, the line goes back to the PIO.
  void stop() {
    silence();
    bus_.write(ssc::kPtcr, ssc::kPtcrTxtdis);
    bus_.write(ssc::kTcr, 0);
    bus_.write(ssc::kTncr, 0);
    left_ = 0;
    playing_ = false;
  }

  void onInterrupt() {
    const uint32_t sr = bus_.read(ssc::kSr);
    if (!playing_) {
      bus_.write(ssc::kIdr, ssc::kSrEndtx | ssc::kSrTxbufe);
      return;
    }
    if (left_ > 0 && (sr & ssc::kSrEndtx)) {
      queueNext();
      if (left_ == 0) {
        bus_.write(ssc::kIdr, ssc::kSrEndtx);
        bus_.write(ssc::kIer, ssc::kSrTxbufe);
      }
    } else if (left_ == 0 && (sr & ssc::kSrTxbufe)) {
      stop();
    }
  }

  bool playing() const { return playing_; }

 private:
  // Words for the next buffer: up to kPeriodsPerBuffer periods of those left.
  uint32_t take() {
    const uint32_t n = left_ < kPeriodsPerBuffer ? (left_ == 0 ? 1 : left_) : kPeriodsPerBuffer;
    left_ = left_ > n ? left_ - n : 0;
    return n * kWordsPerPeriod;
  }
  void queueNext() {
    bus_.write(ssc::kTnpr, bus_.address(wave_));
    bus_.write(ssc::kTncr, take());
  }
  void silence() {
    bus_.write(ssc::kIdr, ssc::kSrEndtx | ssc::kSrTxbufe);
    bus_.write(reg::kPioPer, ssc::kPinTd);
  }

  Bus& bus_;
  uint32_t wave_[kPeriodsPerBuffer * kWordsPerPeriod] = {};  // read by the PDC
  volatile uint32_t left_ = 0;                               // periods not yet queued
  volatile bool playing_ = false;
};

}  // namespace nxtmap::fw
