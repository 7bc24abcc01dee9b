// Spi: the SPI master (0xFFFE0000, ID 5) with its PDC at +0x100, wired to the LCD: each byte shifted out
// goes to the LCD with A0 = the level of PA12 at that moment. 8-bit transfers at MCK/SCBR.
#pragma once

#include "host/emu/IoDevice.hpp"
#include "host/emu/Lcd.hpp"
#include "host/emu/Pdc.hpp"
#include "host/emu/Pioa.hpp"

namespace nxtmap::emu {

class Spi : public IoDevice {
 public:
  static constexpr uint32_t kBase = 0xFFFE0000;
  static constexpr uint32_t kSize = 0x200;
  static constexpr int kA0Pin = 12;
  Spi(Clock& clock, GuestMemory& mem, Pioa& pio, Lcd& lcd) : clock_(clock), pdc_(mem), pio_(pio), lcd_(lcd) {}

  const char* name() const override { return "SPI"; }
  bool read(uint32_t offset, uint32_t& value) override;
  bool write(uint32_t offset, uint32_t value) override;
  bool writeReplans(uint32_t off) const override { return off != 0x04 && (off < 0x30 || off >= 0x100); }
  uint64_t nextEventAt() const override { return shiftDoneAt_; }
  void advanceTo(uint64_t now) override;
  bool irqLine() const { return (status() & imr_) != 0; }

 private:
  uint32_t status() const;
  uint64_t byteCycles() const;
  void feed();

  Clock& clock_;
  Pdc pdc_;
  Pioa& pio_;
  Lcd& lcd_;
  uint32_t mr_ = 0, imr_ = 0, rdr_ = 0;
  uint32_t csr_[4]{};
  bool enabled_ = false;
  bool tdrFull_ = false;
  uint8_t tdr_ = 0, shifting_ = 0;
  bool rdrf_ = false;
  uint64_t shiftDoneAt_ = kNever;
  bool dmaFault_ = false;
};

}  // namespace nxtmap::emu
