#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/Telegram.hpp"
#include "common/protocol/WireFormat.hpp"

namespace nxtmap::protocol {

// The header of an nxtmap packet (see WireFormat.hpp for the byte layout).
struct PacketHeader {
  Op op = Op::Ack;
  uint8_t version = kProtocolVersion;
  uint8_t flags = 0;
  uint16_t seq = 0;      // 0 = unreliable
  uint16_t ack = 0;      // newest reliable seq received from the peer (0 = none yet)
  uint16_t ackMask = 0;  // bit i: seq (ack - 1 - i) received too

  bool reliable() const { return (flags & kFlagReliable) != 0; }
};

// A decoded nxtmap packet: the header and a view of the payload inside the telegram.
struct PacketView {
  PacketHeader header;
  const uint8_t* payload = nullptr;
  size_t payloadSize = 0;
};

// Builds a whole frame (length prefix, header, payload, CRC). False when the payload is larger
// than kMaxPayload.
bool encodePacket(const PacketHeader& header, const uint8_t* payload, size_t payloadSize, Frame& out);

// Parses a telegram that FrameDecoder delivered (CRC already checked). False when it is not an
// nxtmap packet. The view points into `t`.
bool parsePacket(const Telegram& t, PacketView& out);

// The next reliable sequence number after `seq` (1..65535, 0 skipped).
constexpr uint16_t nextSeq(uint16_t seq) { return static_cast<uint16_t>(seq == 0xFFFF ? 1 : seq + 1); }

// Whether the peer's ack/ackMask says `seq` arrived.
constexpr bool acknowledges(uint16_t ack, uint16_t ackMask, uint16_t seq) {
  if (seq == 0 || ack == 0) return false;
  if (seq == ack) return true;
  const uint16_t back = static_cast<uint16_t>(ack - seq);  // 1.. when seq is older
  return back >= 1 && back <= 16 && ((ackMask >> (back - 1)) & 1u) != 0;
}

}  // namespace nxtmap::protocol
