// Usart: USART1 (0xFFFC4000, ID 7) with its PDC at +0x100, asynchronous 8N1 at the rate set by BRGR (CD and the
// fractional FP) and MR.OVER,
// transmit holding + shift register, receive holding register or DMA, receive time-out (RTOR after STTTO).
// Hardware handshaking (US_MR USMODE = 2), as the datasheet states it: RTS is high while the receiver is
// disabled or the PDC's RXBUFF is set (RCR = RNCR = 0), whether or not the receive PDC is enabled, and low
// otherwise; the SerialPeer is told (armRts) and does not send while it is high. Other modes: RTS low
// (RTSEN/RTSDIS not modelled). A byte that arrives with the receive PDC idle goes to RHR (overrun if RXRDY
// is still set). The far end is a SerialPeer.
#pragma once

#include "host/emu/IoDevice.hpp"
#include "host/emu/Pdc.hpp"
#include "host/emu/SerialPeer.hpp"

namespace nxtmap::emu {

class Usart : public IoDevice {
 public:
  static constexpr uint32_t kBase1 = 0xFFFC4000;
  static constexpr uint32_t kSize = 0x200;
  Usart(Clock& clock, GuestMemory& mem, SerialPeer& peer) : clock_(clock), pdc_(mem), peer_(peer) {}

  const char* name() const override { return "USART1"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  bool writeReplans(uint32_t off) const override {
    return off >= 0x100 || (off != 0x04 && off != 0x20 && off != 0x24 && off != 0x28);
  }
  uint64_t nextEventAt() const override;
  void advanceTo(uint64_t now) override;
  bool irqLine() const { return (status() & imr_) != 0; }
  uint64_t bytesSent() const { return sent_; }
  uint64_t bytesReceived() const { return received_; }
  bool dmaFault() const { return dmaFault_; }
  bool rtsHigh() const;  // the RTS pin as driven now
  bool overrun() const { return ovre_; }

 private:
  static constexpr uint32_t kRxrdy = 1, kTxrdy = 2, kEndrx = 8, kEndtx = 16, kOvre = 32, kTimeout = 1u << 8,
                            kTxempty = 1u << 9, kTxbufe = 1u << 11, kRxbuff = 1u << 12;
  uint32_t status() const;
  uint64_t bitCycles() const;
  bool canReceive() const;
  void refillThr();
  void syncRts();  // tells the peer when RTS changes

  Clock& clock_;
  Pdc pdc_;
  SerialPeer& peer_;
  uint32_t mr_ = 0, imr_ = 0, brgr_ = 0, rtor_ = 0, ttgr_ = 0;
  bool rxEn_ = false, txEn_ = false;
  bool thrFull_ = false;
  uint8_t thr_ = 0;
  uint64_t shiftDoneAt_ = kNever;  // end of the byte in the transmit shifter
  uint8_t shifting_ = 0;
  uint64_t rxNextAt_ = kNever;  // when the next byte from the peer has arrived
  bool rxrdy_ = false, ovre_ = false;
  uint8_t rhr_ = 0;
  bool timeoutArmed_ = false, timeout_ = false;
  uint64_t lastRxAt_ = 0;
  bool rxSinceStart_ = false;
  uint64_t sent_ = 0, received_ = 0;
  bool dmaFault_ = false;
  bool rtsToldHigh_ = false;  // RTS level the peer was last told (reset: normal mode, low)
};

}  // namespace nxtmap::emu
