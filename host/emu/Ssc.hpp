// Ssc: the synchronous serial controller (0xFFFD4000, ID 8), transmit side, as the NXT's sound output uses
// it: CR (RXEN/RXDIS/TXEN/TXDIS/SWRST), CMR (DIV: bit clock MCK / (2 * DIV), 0 = off), TCMR, TFMR (DATLEN:
// DATLEN + 1 bits per word; the PDC moves 1, 2 or 4 bytes per word for DATLEN < 8, < 16, else), THR, SR
// (TXRDY, TXEMPTY, ENDTX, TXBUFE, TXEN), IER/IDR/IMR, and its PDC at +0x100. Words leave back to back at the
// bit clock while TXEN is set; what is sent is not kept (no speaker model). The receive side is accepted
// (registers kept) but never receives.
#pragma once

#include "host/emu/IoDevice.hpp"
#include "host/emu/Pdc.hpp"

namespace nxtmap::emu {

class Ssc : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFD4000;
  static constexpr uint32_t kSize = 0x200;
  static constexpr uint32_t kTxrdy = 1, kTxempty = 2, kEndtx = 4, kTxbufe = 8, kTxenStatus = 1u << 16;
  Ssc(Clock& clock, GuestMemory& mem) : clock_(clock), pdc_(mem) {}

  const char* name() const override { return "SSC"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  uint64_t nextEventAt() const override;
  void advanceTo(uint64_t now) override;
  bool irqLine() const { return (status() & imr_) != 0; }
  uint32_t status() const;
  uint64_t wordsSent() const { return words_; }
  bool dmaFault() const { return dmaFault_; }
  // MCK cycles per transmitted word (0: the bit clock is off).
  uint64_t wordCycles() const { return (cmr_ & 0xFFF) * 2 * ((tfmr_ & 0x1F) + 1); }

 private:
  unsigned unitBytes() const { return (tfmr_ & 0x1F) < 8 ? 1 : (tfmr_ & 0x1F) < 16 ? 2 : 4; }
  void reset();
  void start();

  Clock& clock_;
  Pdc pdc_;
  uint32_t cmr_ = 0, rcmr_ = 0, rfmr_ = 0, tcmr_ = 0, tfmr_ = 0, imr_ = 0;
  bool txEn_ = false, thrFull_ = false;
  uint64_t wordEnd_ = kNever;  // end of the word on the line (kNever: idle)
  uint64_t words_ = 0;
  bool dmaFault_ = false;
};

}  // namespace nxtmap::emu
