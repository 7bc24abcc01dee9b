#include "common/protocol/Mailboxes.hpp"

namespace nxtmap::protocol {

uint8_t Mailboxes::write(uint8_t box, const uint8_t* bytes, uint8_t size) {
  if (box >= kLegoMailboxes) return kLegoIllegalMailbox;
  if (size == 0 || size > kLegoMaxMessage || bytes[size - 1] != 0) return kLegoOutOfRange;
  if (count_[box] == kLegoMessagesPerBox) erase(find(box));  // full: the oldest goes
  if (size_t{used_} + 2 + size > kPoolBytes) return kLegoNoMemory;
  pool_[used_] = box;
  pool_[used_ + 1] = size;
  for (uint8_t i = 0; i < size; ++i) pool_[used_ + 2 + i] = bytes[i];
  used_ = static_cast<uint16_t>(used_ + 2 + size);
  ++count_[box];
  return kLegoOk;
}

uint8_t Mailboxes::read(uint8_t box, bool remove, Message& out) {
  if (box >= kLegoMailboxes) return kLegoIllegalMailbox;
  if (count_[box] == 0) return kLegoMailboxEmpty;
  const size_t at = find(box);
  out = Message{};
  out.size = pool_[at + 1];
  for (uint8_t i = 0; i < out.size; ++i) out.bytes[i] = pool_[at + 2 + i];
  if (remove) erase(at);
  return kLegoOk;
}

size_t Mailboxes::find(uint8_t box) const {
  size_t at = 0;
  while (at < used_ && pool_[at] != box) at += 2 + pool_[at + 1];
  return at;
}

void Mailboxes::erase(size_t at) {
  if (at >= used_) return;
  const size_t n = 2 + pool_[at + 1];
  --count_[pool_[at]];
  for (size_t i = at; i + n < used_; ++i) pool_[i] = pool_[i + n];
  used_ = static_cast<uint16_t>(used_ - n);
}

}  // namespace nxtmap::protocol
