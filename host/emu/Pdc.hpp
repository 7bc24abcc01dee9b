// Pdc: a peripheral DMA controller channel pair (at peripheral base + 0x100): receive and transmit
// pointer/counter with the "next" pair chained in when a counter reaches 0, or at once when the next
// counter is written non-zero while the current counter is 0 (datasheet PDC: the next buffer becomes the
// current one). Counters count transfers of the peripheral's unit (1 byte, or 2 or 4 for the SSC's
// longer words). nxt-hardware.md 1.3.
#pragma once

#include "host/emu/IoDevice.hpp"

namespace nxtmap::emu {

class Pdc {
 public:
  explicit Pdc(GuestMemory& mem) : mem_(mem) {}
  // offset from the PDC base (0x00..0x24); false = not a PDC register.
  bool read(uint32_t offset, uint32_t& value) const;
  bool write(uint32_t offset, uint32_t value);

  bool txActive() const { return txEn_ && tcr_ > 0; }
  bool rxActive() const { return rxEn_ && rcr_ > 0; }
  bool rxEnabled() const { return rxEn_; }
  // Next byte to send (call only when txActive); false if the pointer is outside memory.
  bool takeTx(uint8_t& byte);
  // The next transfer of `bytes` (1, 2 or 4) bytes, little-endian (call only when txActive).
  bool takeTxUnit(uint32_t& value, unsigned bytes);
  uint32_t txCount() const { return tcr_; }
  // Stores a received byte (call only when rxActive); false if the pointer is outside RAM.
  bool putRx(uint8_t byte);
  bool endTx() const { return tcr_ == 0; }
  bool txBufferEmpty() const { return tcr_ == 0 && tncr_ == 0; }
  bool endRx() const { return rcr_ == 0; }
  bool rxBufferFull() const { return rcr_ == 0 && rncr_ == 0; }

 private:
  void chainTx();
  void chainRx();
  GuestMemory& mem_;
  uint32_t rpr_ = 0, rcr_ = 0, tpr_ = 0, tcr_ = 0, rnpr_ = 0, rncr_ = 0, tnpr_ = 0, tncr_ = 0;
  bool rxEn_ = false, txEn_ = false;
};

}  // namespace nxtmap::emu
