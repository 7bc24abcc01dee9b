#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/WireFormat.hpp"

namespace nxtmap::protocol {

// The payload bytes of one nxtmap packet, as an encoder writes them (size 0 = nothing written).
struct Payload {
  uint8_t bytes[kMaxPayload] = {};
  size_t size = 0;
};

}  // namespace nxtmap::protocol
