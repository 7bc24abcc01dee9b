#pragma once
#include <cstdint>

#include "firmware/drivers/StreamFramer.hpp"

namespace nxtmap::fw {

// The application's radio side, behind one seam: bytes in and out of the BlueCore stream. It
// splits the stream into NXT telegrams (2-byte little-endian length) and is where the wire
// protocol (common/protocol) plugs in: received telegrams become commands, and the map, pose and
// counters become outgoing frames. Until that protocol is merged, telegrams are only counted.
class RadioSeam {
 public:
  // One byte from the PC.
  void receive(uint8_t b) {
    if (decoder_.push(b)) ++telegrams_;
  }
  // The stream ended (PC gone): any half telegram is dropped.
  void linkLost() { decoder_.reset(); }
  uint32_t telegrams() const { return telegrams_; }
  uint32_t oversized() const { return decoder_.oversized(); }

 private:
  StreamDecoder decoder_;
  uint32_t telegrams_ = 0;
};

}  // namespace nxtmap::fw
