#include "common/protocol/Mailboxes.hpp"

namespace nxtmap::protocol {

bool Mailboxes::write(uint8_t box, const uint8_t* bytes, uint8_t size) {
  if (box >= kLegoMailboxes || size == 0 || size > kLegoMaxMessage || bytes[size - 1] != 0) return false;
  if (count_[box] == kDepth) {  // full: drop the oldest
    first_[box] = static_cast<uint8_t>((first_[box] + 1) % kDepth);
    --count_[box];
  }
  Message& m = queue_[box][(first_[box] + count_[box]) % kDepth];
  m.size = size;
  for (uint8_t i = 0; i < kLegoMaxMessage; ++i) m.bytes[i] = i < size ? bytes[i] : 0;
  ++count_[box];
  return true;
}

bool Mailboxes::read(uint8_t box, bool remove, Message& out) {
  if (box >= kLegoMailboxes || count_[box] == 0) return false;
  out = queue_[box][first_[box]];
  if (remove) {
    first_[box] = static_cast<uint8_t>((first_[box] + 1) % kDepth);
    --count_[box];
  }
  return true;
}

}  // namespace nxtmap::protocol
