// Twi: the TWI master (0xFFFB8000) wired to the AVR model. Byte-level with bus timing from CWGR
// (9 bit times per byte). A write frame (MMR.MREAD 0) starts when THR is written, or at CR.START (START
// and the address go out at once; the AT91SAM7S datasheet: "a frame beginning with a START bit is
// transmitted according to the features defined in the mode register"). Each byte moves from THR into
// the shifter at the end of the one before (TXRDY rises); when THR and the shifter are both empty the
// TWI sends STOP by itself, so a START with nothing written to THR is an address-only frame. STOP
// asked in a write (the SAM7S datasheet defines it for master read only) takes effect after the data
// byte on the wire, as later TWI datasheets say: a byte still in THR then starts a frame of its own.
// Read frames start with CR.START and end after the byte during which STOP was asked. TXCOMP is clear
// from a frame's start to its STOP. Status TXCOMP/RXRDY/TXRDY/NACK, interrupt ID 9. A frame to
// another address is NACKed.
#pragma once

#include "host/emu/AvrModel.hpp"
#include "host/emu/IoDevice.hpp"

#include <vector>

namespace nxtmap::emu {

class Twi : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFB8000;
  static constexpr uint32_t kSize = 0x100;
  Twi(Clock& clock, AvrModel& avr) : clock_(clock), avr_(avr) {}

  const char* name() const override { return "TWI"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  bool writeReplans(uint32_t off) const override { return off != 0x04 && off != 0x0C && off != 0x10; }
  uint64_t nextEventAt() const override { return busyUntil_; }
  void advanceTo(uint64_t now) override;
  bool irqLine() const { return (sr_ & imr_) != 0; }
  uint64_t frames() const { return frames_; }  // frames ended by a STOP (address-only ones included)

 private:
  static constexpr uint32_t kTxcomp = 1, kRxrdy = 2, kTxrdy = 4, kOvre = 1u << 6, kNack = 1u << 8;
  uint64_t byteCycles() const;
  void reset();
  void startByte();
  void startWriteFrame();
  void endFrame();

  Clock& clock_;
  AvrModel& avr_;
  uint32_t mmr_ = 0, iadr_ = 0, cwgr_ = 0, imr_ = 0, rhr_ = 0;
  uint32_t sr_ = kTxcomp | kTxrdy;
  bool enabled_ = false;
  bool inFrame_ = false, reading_ = false, stopAsked_ = false;
  bool thrFull_ = false;
  bool dataOnWire_ = false;  // write frames: a data byte (not the address) is being sent
  uint8_t thr_ = 0;
  uint64_t busyUntil_ = kNever;  // end of the byte on the wire
  std::vector<uint8_t> frame_;
  size_t readIndex_ = 0;
  std::array<uint8_t, 13> reply_{};
  uint64_t frames_ = 0;
};

}  // namespace nxtmap::emu
