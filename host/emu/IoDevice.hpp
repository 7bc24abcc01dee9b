// IoDevice: one peripheral model behind the MMIO dispatcher (MmioBus). Registers are 32-bit words at
// word offsets from the device base. A device answers false for a register it does not model, and the
// machine stops the run loudly with the PC and the address.
#pragma once

#include "host/emu/Clock.hpp"

#include <cstddef>
#include <cstdint>

namespace nxtmap::emu {

class IoDevice {
 public:
  virtual ~IoDevice() = default;
  virtual const char* name() const = 0;
  // offset: bytes from the device base (multiple of 4). false = register not modelled.
  virtual bool read(uint32_t offset, uint32_t& value) = 0;
  virtual bool write(uint32_t offset, uint32_t value) = 0;
  // Whether a write to this register can change interrupt or timing state, so the machine must re-plan
  // at the next block boundary (conservative default: yes). Pure configuration registers say no.
  virtual bool writeReplans(uint32_t /*offset*/) const { return true; }
  // Time: the next cycle at which the device changes state on its own (kNever if none), and
  // advancing its state to `now` (called with non-decreasing times).
  virtual uint64_t nextEventAt() const { return kNever; }
  virtual void advanceTo(uint64_t /*now*/) {}
};

// Access to guest memory for DMA (PDC) and the host, by bus address. false = outside RAM/flash.
class GuestMemory {
 public:
  virtual ~GuestMemory() = default;
  virtual bool readByte(uint32_t address, uint8_t& value) const = 0;
  virtual bool writeByte(uint32_t address, uint8_t value) = 0;
};

}  // namespace nxtmap::emu
