#include "common/protocol/Packet.hpp"

#include "common/protocol/ByteWriter.hpp"
#include "common/protocol/Crc32.hpp"

namespace nxtmap::protocol {

bool encodePacket(const PacketHeader& h, const uint8_t* payload, size_t payloadSize, Frame& out) {
  if (payloadSize > kMaxPayload) return false;
  const size_t telegramSize = kPacketHeader + payloadSize + kPacketTrailer;
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u16(static_cast<uint16_t>(telegramSize));
  w.u8(kTypeNxtmap);
  w.u8(static_cast<uint8_t>(h.op));
  w.u8(h.version);
  w.u8(h.flags);
  w.u16(h.seq);
  w.u16(h.ack);
  w.u16(h.ackMask);
  w.bytes(payload, payloadSize);
  w.u32(crc32(out.bytes + kLengthPrefix, kPacketHeader + payloadSize));
  if (!w.ok()) return false;
  out.size = static_cast<uint8_t>(w.size());
  return true;
}

bool parsePacket(const Telegram& t, PacketView& out) {
  if (t.size < kPacketHeader + kPacketTrailer || t.bytes[0] != kTypeNxtmap) return false;
  const uint8_t* b = t.bytes;
  out.header.op = static_cast<Op>(b[1]);
  out.header.version = b[2];
  out.header.flags = b[3];
  out.header.seq = static_cast<uint16_t>(b[4] | (b[5] << 8));
  out.header.ack = static_cast<uint16_t>(b[6] | (b[7] << 8));
  out.header.ackMask = static_cast<uint16_t>(b[8] | (b[9] << 8));
  out.payload = b + kPacketHeader;
  out.payloadSize = t.size - kPacketHeader - kPacketTrailer;
  return true;
}

}  // namespace nxtmap::protocol
