#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/LegoFormat.hpp"

namespace nxtmap::protocol {

// LEGO's message queues, as MESSAGE_WRITE and MESSAGE_READ see them: 20 queues of up to 5 text
// messages each (1..59 bytes including the terminating NUL). LEGO's overflow rule: writing to a full
// queue drops its oldest message. The messages of all queues share one pool of kPoolBytes (LEGO's
// share its dataspace); a write that does not fit even then is refused with kLegoNoMemory.
class Mailboxes {
 public:
  // Five full messages (one full queue) or many short ones.
  static constexpr size_t kPoolBytes = 320;

  struct Message {
    uint8_t size = 0;  // bytes including the NUL, 1..59
    uint8_t bytes[kLegoMaxMessage] = {};
  };

  // Appends a message (size includes the NUL; the last byte must be 0). Returns LEGO's status:
  // kLegoOk, kLegoIllegalMailbox (box >= 20), kLegoOutOfRange (bad size or no NUL), kLegoNoMemory.
  uint8_t write(uint8_t box, const uint8_t* bytes, uint8_t size);
  // Oldest message of the box, optionally removing it: kLegoOk, kLegoMailboxEmpty, kLegoIllegalMailbox.
  uint8_t read(uint8_t box, bool remove, Message& out);
  uint8_t count(uint8_t box) const { return box < kLegoMailboxes ? count_[box] : 0; }
  // Pool bytes in use (each message takes its size + 2).
  size_t used() const { return used_; }

 private:
  // Pool entries, oldest first: [box][size][size bytes].
  size_t find(uint8_t box) const;  // offset of the box's oldest entry (used_ when none)
  void erase(size_t at);

  uint8_t pool_[kPoolBytes] = {};
  uint16_t used_ = 0;
  uint8_t count_[kLegoMailboxes] = {};
};

static_assert(sizeof(Mailboxes) <= Mailboxes::kPoolBytes + kLegoMailboxes + 8, "mailboxes: the pool and a count each");
static_assert(Mailboxes::kPoolBytes >= kLegoMessagesPerBox * (kLegoMaxMessage + 2), "one queue of full messages fits");

}  // namespace nxtmap::protocol
