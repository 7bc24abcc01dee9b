// SerialPeer: what sits at the far end of a UART: takes the bytes the ARM sends and offers bytes to it.
#pragma once

#include <cstdint>

namespace nxtmap::emu {

class SerialPeer {
 public:
  virtual ~SerialPeer() = default;
  virtual void fromArm(uint8_t byte) = 0;
  virtual bool hasByteForArm() const = 0;
  virtual uint8_t takeByteForArm() = 0;
  // The ARM's RTS line (the peer's CTS): high = the peer must not start a byte to the ARM.
  virtual void armRts(bool high) { (void)high; }
};

}  // namespace nxtmap::emu
