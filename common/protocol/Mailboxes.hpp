#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/WireFormat.hpp"

namespace nxtmap::protocol {

// LEGO's message mailboxes, as MESSAGE_WRITE and MESSAGE_READ see them: 10 queues of text
// messages of up to 59 bytes including the terminating NUL. LEGO keeps 5 messages per queue;
// the brick keeps kDepth (RAM), dropping the oldest when a queue is full, as LEGO does.
class Mailboxes {
 public:
  static constexpr uint8_t kDepth = 2;

  struct Message {
    uint8_t size = 0;  // bytes including the NUL, 1..59
    uint8_t bytes[kLegoMaxMessage] = {};
  };

  // Appends a message (size includes the NUL; the last byte must be 0). False for a bad box or size.
  bool write(uint8_t box, const uint8_t* bytes, uint8_t size);
  // Oldest message of the box, optionally removing it. False when empty or a bad box.
  bool read(uint8_t box, bool remove, Message& out);
  uint8_t count(uint8_t box) const { return box < kLegoMailboxes ? count_[box] : 0; }

 private:
  Message queue_[kLegoMailboxes][kDepth] = {};
  uint8_t first_[kLegoMailboxes] = {};
  uint8_t count_[kLegoMailboxes] = {};
};

}  // namespace nxtmap::protocol
