#include "common/protocol/LegoServer.hpp"

#include "common/protocol/ByteWriter.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap::protocol {
namespace {

constexpr char kDefaultName[] = "nxtmap";

uint16_t u16At(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
uint32_t u32At(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
         (static_cast<uint32_t>(p[3]) << 24);
}

void writeOutput(ByteWriter& w, uint8_t port, const LegoOutputState& s) {
  w.u8(port);
  w.u8(static_cast<uint8_t>(s.power));
  w.u8(s.mode);
  w.u8(s.regulation);
  w.u8(static_cast<uint8_t>(s.turnRatio));
  w.u8(s.runState);
  w.u32(s.tachoLimit);
  w.u32(static_cast<uint32_t>(s.tachoCount));
  w.u32(static_cast<uint32_t>(s.blockTachoCount));
  w.u32(static_cast<uint32_t>(s.rotationCount));
}

void writeInput(ByteWriter& w, uint8_t port, const LegoInputValues& v) {
  w.u8(port);
  w.u8(v.valid ? 1 : 0);
  w.u8(0);  // calibrated: never (LEGO's firmware has no calibration either)
  w.u8(v.sensorType);
  w.u8(v.sensorMode);
  w.u16(v.raw);
  w.u16(v.normalized);
  w.i16(v.scaled);
  w.i16(v.calibrated);
}

}  // namespace

NXTMAP_RUN_ONCE LegoServer::LegoServer() {
  for (size_t i = 0; i + 1 < sizeof(kDefaultName); ++i) name_[i] = kDefaultName[i];
}

void LegoServer::take(const Telegram& t) {
  if (t.size < 2 || !isLegoCommandType(t.type())) return;  // replies: the brick asked nothing
  const bool served = legoReplySize(t.type(), t.opcode()) != 0;
  const bool wellFormed = served && legoTelegramKnown(t.bytes, t.size);
  if (!legoReplyWanted(t.type()) && !wellFormed) return;  // nothing to do, nobody waits
  // A command that cannot be carried out is queued as [type][opcode] alone: its answer is a status.
  const size_t n = wellFormed ? t.size : 2;
  if (kQueueBytes - used_ < 1 + n) {
    ++dropped_;
    return;
  }
  const uint8_t header = static_cast<uint8_t>(n | (wellFormed ? 0 : kMalformed));
  push(&header, 1);
  push(t.bytes, n);
}

void LegoServer::push(const uint8_t* bytes, size_t n) {
  for (size_t i = 0; i < n; ++i) ring_[(head_ + used_ + i) % kQueueBytes] = bytes[i];
  used_ += n;
}

bool LegoServer::next(const LegoContext& ctx, LegoBrick& brick, Frame& out) {
  while (used_ > 0) {
    uint8_t c[kMaxTelegram];
    const uint8_t header = at(0);
    const size_t n = header & ~kMalformed;
    for (size_t i = 0; i < n; ++i) c[i] = at(1 + i);
    head_ = (head_ + 1 + n) % kQueueBytes;
    used_ -= 1 + n;
    uint8_t* reply = out.bytes + kLengthPrefix;
    carryOut(c, n, (header & kMalformed) == 0, ctx, brick, reply);
    if (!legoReplyWanted(c[0])) continue;
    const size_t served = legoReplySize(c[0], c[1]);
    return frameTelegram(reply, served == 0 ? kLegoStatusReplySize : served, out);
  }
  return false;
}

// `reply` receives [02][opcode][status][fields, zero-filled when the status is not kLegoOk].
void LegoServer::carryOut(const uint8_t* c, size_t n, bool wellFormed, const LegoContext& ctx, LegoBrick& brick,
                          uint8_t* reply) {
  const size_t size = legoReplySize(c[0], c[1]);
  for (size_t i = 0; i < kMaxTelegram; ++i) reply[i] = 0;
  reply[0] = kTypeReply;
  reply[1] = c[1];
  if (size == 0) {
    reply[2] = kLegoUnknownCommand;
    return;
  }
  if (!wellFormed) {
    reply[2] = kLegoInsanePacket;
    return;
  }
  ByteWriter w(reply + 3, size - 3);
  uint8_t st = kLegoOk;
  switch (c[1]) {
    case kLegoPlayTone: brick.playTone(u16At(c + 2), u16At(c + 4)); break;
    case kLegoStopSoundPlayback: brick.stopSound(); break;
    case kLegoSetOutputState: st = setOutputs(c, ctx, brick); break;
    case kLegoResetMotorPosition:
      st = c[2] >= kLegoOutputs ? kLegoOutOfRange
           : ctx.motorsBusy     ? kLegoRequestFailed
                                : brick.resetPosition(c[2], c[3] != 0);
      break;
    case kLegoGetOutputState:
      if (c[2] >= kLegoOutputs)
        st = kLegoOutOfRange;
      else
        writeOutput(w, c[2], brick.output(c[2]));
      break;
    case kLegoGetInputValues:
      if (c[2] >= kLegoInputs)
        st = kLegoOutOfRange;
      else
        writeInput(w, c[2], brick.input(c[2]));
      break;
    case kLegoGetBatteryLevel: w.u16(ctx.batteryMillivolts); break;
    case kLegoKeepAlive: w.u32(ctx.sleepLimitMs); break;
    case kLegoMessageWrite: st = boxes_.write(c[2], c + 4, c[3]); break;
    case kLegoMessageRead: {
      Mailboxes::Message m;
      st = boxes_.read(c[2], c[4] != 0, m);
      w.u8(c[3]);  // the asker's local inbox, echoed
      w.u8(st == kLegoOk ? m.size : 0);
      w.bytes(m.bytes, kLegoMaxMessage);
      break;
    }
    case kLegoGetFirmwareVersion:
      w.u8(kLegoProtocolMinor);
      w.u8(kLegoProtocolMajor);
      w.u8(ctx.firmwareMinor);
      w.u8(0);
      break;
    case kLegoSetBrickName: setName(c, n); break;
    case kLegoGetDeviceInfo: {
      w.bytes(reinterpret_cast<const uint8_t*>(name_), kLegoNameChars);
      uint8_t a[6];
      brick.address(a);
      w.bytes(a, sizeof(a));
      w.u8(0);   // LEGO's seventh address byte, unused
      w.u32(0);  // signal strengths: not measured
      w.u32(brick.freeFlashBytes());
      break;
    }
    default: break;
  }
  reply[2] = st;
  if (st != kLegoOk && c[1] != kLegoMessageRead) {
    for (size_t i = 3; i < size; ++i) reply[i] = 0;
  }
}

uint8_t LegoServer::setOutputs(const uint8_t* c, const LegoContext& ctx, LegoBrick& brick) {
  const uint8_t port = c[2];
  if (port >= kLegoOutputs && port != kLegoAllOutputs) return kLegoOutOfRange;
  if (ctx.motorsBusy) return kLegoRequestFailed;
  LegoOutputCommand o;
  o.power = static_cast<int8_t>(c[3]);
  o.mode = c[4];
  o.regulation = c[5];
  o.turnRatio = static_cast<int8_t>(c[6]);
  o.runState = c[7];
  o.tachoLimit = u32At(c + 8);
  if (o.power < -100 || o.power > 100) return kLegoOutOfRange;
  const uint8_t first = port == kLegoAllOutputs ? 0 : port;
  const uint8_t last = port == kLegoAllOutputs ? kLegoOutputs - 1 : port;
  uint8_t st = kLegoOk;
  for (uint8_t p = first; p <= last; ++p) {
    o.port = p;
    const uint8_t s = brick.setOutput(o);
    if (st == kLegoOk) st = s;
  }
  return st;
}

void LegoServer::setName(const uint8_t* c, size_t n) {
  size_t k = 0;
  for (; k < kLegoNameChars && 2 + k < n && c[2 + k] != 0; ++k) name_[k] = static_cast<char>(c[2 + k]);
  for (; k <= kLegoNameChars; ++k) name_[k] = '\0';
}

}  // namespace nxtmap::protocol
