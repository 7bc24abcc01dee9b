#include "common/protocol/BrickLink.hpp"

#include <new>

#include "common/protocol/Packet.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap::protocol {
NXTMAP_RUN_ONCE BrickLink::BrickLink(const RoomGrid& grid, uint8_t* shadow, const BrickLinkConfig& config)
    : config_(config), sync_(grid, shadow, config.retransmitMs) {}

void BrickLink::receive(uint8_t byte) {
  decoder_.push(byte);
  Telegram t;
  while (decoder_.pop(t)) handle(t);
  counters_.bytesSkipped = decoder_.counters().skipped;
}

void BrickLink::handle(const Telegram& t) {
  ++counters_.telegramsIn;
  if (isLegoType(t.type())) {
    lego_.take(t);  // carried out and answered in transmit(), where the brick's state is known
    return;
  }
  if (t.type() == kTypeNxtmap) handlePacket(t);
}

void BrickLink::handlePacket(const Telegram& t) {
  PacketView v;
  if (!parsePacket(t, v)) return;
  if (v.header.op == Op::Hello) {
    handleHello(v.payload, v.payloadSize);
    return;
  }
  if (v.header.version != kProtocolVersion || !connected_) return;
  // The PC sends other packets only after a HelloReply reached it, and every reply said "fresh"
  // until now: from here on a Hello of this session is a reconnect.
  freshSession_ = false;
  const int inFlight = sync_.inFlight();
  sync_.acknowledge(v.header.ack, v.header.ackMask, nowMs_);
  if (sync_.inFlight() < inFlight) scanNow_ = true;  // room for the next delta
  switch (v.header.op) {
    case Op::Explore:
    case Op::Stop:
    case Op::FollowPath:
    case Op::RequestMap:
    case Op::MapChunk:
    case Op::SetPose:
    case Op::GoTo:
    case Op::EnterRoom:
    case Op::Scan:
    case Op::Calibrate: handleCommand(v.header, v.payload, v.payloadSize); break;
    case Op::BatteryRequest: batteryDue_ = true; break;
    default: break;  // Ack (already applied) and anything the brick does not take
  }
}

void BrickLink::handleHello(const uint8_t* p, size_t n) {
  HelloMsg hello;
  if (!decodeHello(p, n, hello)) return;
  helloReplyDue_ = true;
  if (hello.version != kProtocolVersion) {
    connected_ = false;  // answer with our version so the PC can say why it gives up
    return;
  }
  if (!hasSession_ || hello.session != session_) {
    // A PC we have not talked to since power-on: fresh duplicate tracking, the whole map.
    hasSession_ = true;
    session_ = hello.session;
    freshSession_ = true;
    commands_.reset();
    sync_.restart();
  } else if (hello.wantMap) {
    sync_.restart();
  } else {
    sync_.linkLost();  // whatever was in flight before the reconnect goes again
  }
  connected_ = true;
  scanNow_ = true;
  stateDue_ = true;
  statusSent_ = false;
}

void BrickLink::handleCommand(const PacketHeader& h, const uint8_t* p, size_t n) {
  if (!h.reliable() || h.seq == 0) return;
  if (commands_.seen(h.seq)) {
    ++counters_.duplicates;
    ackDue_ = true;
    return;
  }
  Command c;
  c.seq = h.seq;
  bool valid = n == 0;
  switch (h.op) {
    case Op::Explore:
      c.kind = CommandKind::Explore;
      new (&c.explore) ExploreMsg();
      valid = n == 0 || decodeExplore(p, n, c.explore);  // empty: the frontier explorer, not confined
      break;
    case Op::GoTo:
      c.kind = CommandKind::GoTo;
      valid = decodeGoTo(p, n, *new (&c.goTo) GoToMsg());
      break;
    case Op::EnterRoom:
      c.kind = CommandKind::EnterRoom;
      valid = decodeEnterRoom(p, n, *new (&c.enterRoom) EnterRoomMsg());
      break;
    case Op::Scan:
      c.kind = CommandKind::Scan;
      valid = decodeScan(p, n, *new (&c.scan) ScanMsg());
      break;
    case Op::Stop: c.kind = CommandKind::Stop; break;
    case Op::Calibrate: c.kind = CommandKind::Calibrate; break;
    case Op::RequestMap:
      if (valid) {
        sync_.restart();
        scanNow_ = true;
      }
      commands_.record(h.seq);
      ackDue_ = true;
      return;
    case Op::FollowPath:
      c.kind = CommandKind::FollowPath;
      valid = decodePath(p, n, *new (&c.path) PathMsg());
      break;
    case Op::MapChunk:
      c.kind = CommandKind::MapChunk;
      valid = decodeMapChunk(p, n, *new (&c.chunk) MapChunkMsg());
      break;
    case Op::SetPose: {
      c.kind = CommandKind::SetPose;
      PoseMsg m;
      valid = decodePose(p, n, m);
      new (&c.pose) Pose(m.pose);
      break;
    }
    default: return;
  }
  if (!valid) {
    // A well-formed packet with a malformed command: never run it, but acknowledge it so the
    // PC does not send it forever.
    commands_.record(h.seq);
    ackDue_ = true;
    return;
  }
  if (queueCount_ == kCommandQueue) return;  // no room: not acknowledged, the PC sends it again
  queue_[(queueFirst_ + queueCount_) % kCommandQueue] = c;
  ++queueCount_;
  commands_.record(h.seq);
  ackDue_ = true;
}

bool BrickLink::nextCommand(Command& out) {
  if (queueCount_ == 0) return false;
  out = queue_[queueFirst_];
  queueFirst_ = static_cast<uint8_t>((queueFirst_ + 1) % kCommandQueue);
  --queueCount_;
  ++counters_.commandsRun;
  return true;
}

void BrickLink::linkLost() {
  connected_ = false;
  decoder_.reset();
  sync_.linkLost();
  helloReplyDue_ = false;
  ackDue_ = false;
  batteryDue_ = false;
  lego_.forget();
}

bool BrickLink::send(Op op, bool reliable, const Payload& payload, Frame& out) {
  PacketHeader h;
  h.op = op;
  h.flags = reliable ? kFlagReliable : 0;
  h.seq = reliable ? txSeq_ : 0;
  h.ack = commands_.ack();
  h.ackMask = commands_.ackMask();
  ackDue_ = false;
  return encodePacket(h, payload.bytes, payload.size, out);
}

}  // namespace nxtmap::protocol
