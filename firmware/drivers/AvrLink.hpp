#pragma once
#include <cstdint>

#include "firmware/board/At91sam7s.hpp"
#include "firmware/drivers/AvrFrame.hpp"

namespace nxtmap::fw {

// The TWI master side of the AVR link. tick() runs in the 1 ms timer interrupt, onInterrupt()
// in the TWI interrupt (highest priority, edge-triggered: one interrupt per rising TXRDY/RXRDY/NACK).
// Sequence: bus reset -> handshake (47 bytes) -> 2 ms pause -> then alternately one 9-byte command
// write and one 13-byte status read, one transfer every kTransferPeriodMs ticks (LEGO's firmware uses
// 1 ms; 2 ms still puts a new motor command on the wire every 4 ms and halves the TWI interrupt load).
// Done as LEGO's d_ioctrl.r does it on the same chip: a write starts when its first byte is written to
// THR (no START) and ends with the STOP the TWI sends by itself once THR and the shifter are empty (no
// STOP asked); a read starts with START and asks STOP while its last byte arrives; the next transfer
// starts only once SR.TXCOMP says the previous STOP went out. A transfer still busy after kTimeoutMs,
// a NACK, or kMaxBadFrames bad checksums in a row restart from the handshake. Every transfer ends with
// the TWI's interrupts disabled: its line to the AIC is SR & IMR, and TXRDY stays set after a write, so
// a bit left enabled would hold the edge-triggered line high and the next read's RXRDY would make no
// edge: the read would stall to the time-out and the link would keep restarting.
// Bus: read(addr) / write(addr, value) register access.
template <class Bus>
class AvrLink {
 public:
  enum class State : uint8_t { Down, Handshake, Settle, Send, Receive };
  static constexpr uint8_t kTimeoutMs = 30;
  static constexpr uint8_t kMaxBadFrames = 3;
  static constexpr uint8_t kSettleMs = 2;
  static constexpr uint8_t kTransferPeriodMs = 2;

  explicit AvrLink(Bus& bus) : bus_(bus) {}

  // Takes the pins and the TWI (call once, interrupts off).
  void init() {
    using namespace reg;
    bus_.write(kPmcPcer, (1u << kIdTwi) | (1u << kIdPioa));
    bus_.write(kTwiIdr, ~0u);
    // Free a slave stuck mid-byte: clock SCL as PIO until SDA reads high (at most 9 clocks).
    bus_.write(kPioMder, kPinTwd | kPinTwck);
    bus_.write(kPioPer, kPinTwd | kPinTwck);
    bus_.write(kPioOdr, kPinTwd);
    bus_.write(kPioOer, kPinTwck);
    for (int i = 0; i < 9 && (bus_.read(kPioPdsr) & kPinTwd) == 0; ++i) {
      bus_.write(kPioCodr, kPinTwck);
      bus_.write(kPioSodr, kPinTwck);
    }
    bus_.write(kPioPdr, kPinTwd | kPinTwck);
    bus_.write(kPioAsr, kPinTwd | kPinTwck);
    resetTwi();
    state_ = State::Down;
  }

  // The command sent in every frame from now on (fields are single bytes: safe to set from main).
  AvrCommand& command() { return command_; }
  // The last status with a good checksum.
  const AvrStatus& status() const { return status_; }
  State state() const { return state_; }
  bool up() const { return state_ == State::Send || state_ == State::Receive; }
  uint32_t goodFrames() const { return goodFrames_; }
  uint32_t badFrames() const { return badFrames_; }
  uint32_t restarts() const { return restarts_; }
  // Milliseconds since the last good status frame (saturates).
  uint16_t silentMs() const { return silentMs_; }

  // 1 ms tick: starts the next transfer when the previous one is over.
  void tick() {
    if (silentMs_ < 0xFFFF) ++silentMs_;
    if (busy_ || !lineFree()) {
      if (++busyMs_ >= kTimeoutMs) restart();
      return;
    }
    switch (state_) {
      case State::Down:
        packAvrHandshake(buf_);
        startWrite(kAvrHandshakeBytes);
        state_ = State::Handshake;
        break;
      case State::Handshake:
        waitMs_ = kSettleMs;
        state_ = State::Settle;
        break;
      case State::Settle:
        if (--waitMs_ == 0) {
          state_ = State::Send;
          periodMs_ = kTransferPeriodMs - 1;  // the first command goes out on the next tick
        }
        break;
      case State::Send:
        if (++periodMs_ < kTransferPeriodMs) break;
        periodMs_ = 0;
        packAvrCommand(command_, buf_);
        startWrite(kAvrTxBytes);
        state_ = State::Receive;
        break;
      case State::Receive:
        if (++periodMs_ < kTransferPeriodMs) break;
        periodMs_ = 0;
        startRead(kAvrRxBytes);
        state_ = State::Send;
        break;
    }
  }

  // TWI interrupt: moves one byte. Reading SR acknowledges it.
  void onInterrupt() {
    using namespace reg;
    const uint32_t sr = bus_.read(kTwiSr);
    if (!busy_) return;
    if (sr & (kTwiSrNack | kTwiSrOvre | kTwiSrUnre)) {
      bus_.write(kTwiCr, kTwiCrStop);
      bus_.write(kTwiIdr, ~0u);
      busy_ = false;
      restart();
      return;
    }
    if (reading_) {
      if (!(sr & kTwiSrRxrdy)) return;
      buf_[pos_++] = static_cast<uint8_t>(bus_.read(kTwiRhr));
      if (len_ - pos_ == 1) bus_.write(kTwiCr, kTwiCrStop);
      if (pos_ == len_) {
        bus_.write(kTwiIdr, ~0u);
        busy_ = false;
        finishRead();
      }
    } else {
      if (!(sr & kTwiSrTxrdy)) return;
      if (pos_ == len_) {  // the last byte is in the shifter: the TWI sends STOP after it by itself
        bus_.write(kTwiIdr, ~0u);
        busy_ = false;
        return;
      }
      bus_.write(kTwiThr, buf_[pos_++]);
    }
  }

 private:
  // The first byte in THR starts the frame (START and the address go first); TXRDY is enabled after
  // it, so its interrupt comes when that byte moves into the shifter.
  void startWrite(uint8_t n) {
    using namespace reg;
    begin(n, false);
    bus_.write(kTwiCr, kTwiCrMsen);
    bus_.write(kTwiMmr, static_cast<uint32_t>(kAvrAddress) << 16);
    bus_.write(kTwiThr, buf_[pos_++]);
    bus_.write(kTwiIer, kTwiSrTxrdy | kTwiSrNack);
  }
  void startRead(uint8_t n) {
    using namespace reg;
    begin(n, true);
    bus_.write(kTwiMmr, (static_cast<uint32_t>(kAvrAddress) << 16) | kTwiMmrMread);
    bus_.write(kTwiCr, kTwiCrStart | kTwiCrMsen);
    bus_.write(kTwiIer, kTwiSrRxrdy | kTwiSrNack);
  }
  // The previous frame's STOP is out (TXCOMP). A NACK seen here (after the last byte) restarts.
  bool lineFree() {
    using namespace reg;
    const uint32_t sr = bus_.read(kTwiSr);
    if (sr & kTwiSrNack) {
      restart();
      return false;
    }
    return (sr & kTwiSrTxcomp) != 0;
  }
  void begin(uint8_t n, bool reading) {
    len_ = n;
    pos_ = 0;
    reading_ = reading;
    busy_ = true;
    busyMs_ = 0;
  }
  void finishRead() {
    if (parseAvrStatus(buf_, status_)) {
      ++goodFrames_;
      badInRow_ = 0;
      silentMs_ = 0;
    } else {
      ++badFrames_;
      if (++badInRow_ >= kMaxBadFrames) restart();
    }
  }
  // A software reset clears every TWI register, the clock's waveform too (SAM7S datasheet, TWI_CR.SWRST): it is
  // set again, or the next frames run at a few MHz and every read overruns.
  void resetTwi() {
    using namespace reg;
    constexpr uint32_t div = (kMck / 400000u) / 2u - 3u;  // SCL at 400 kHz
    bus_.write(kTwiIdr, ~0u);
    bus_.write(kTwiCr, kTwiCrSwrst | kTwiCrMsdis);
    bus_.write(kTwiCwgr, div | (div << 8));
    bus_.write(kTwiCr, kTwiCrMsen);
  }
  void restart() {
    resetTwi();
    busy_ = false;
    busyMs_ = 0;
    badInRow_ = 0;
    ++restarts_;
    state_ = State::Down;
  }

  Bus& bus_;
  AvrCommand command_{};
  AvrStatus status_{};
  uint8_t buf_[kAvrHandshakeBytes] = {};
  volatile State state_ = State::Down;
  volatile bool busy_ = false;
  bool reading_ = false;
  uint8_t len_ = 0, pos_ = 0;
  uint8_t busyMs_ = 0, waitMs_ = 0, badInRow_ = 0, periodMs_ = 0;
  uint16_t silentMs_ = 0xFFFF;
  uint32_t goodFrames_ = 0, badFrames_ = 0, restarts_ = 0;
};

}  // namespace nxtmap::fw
