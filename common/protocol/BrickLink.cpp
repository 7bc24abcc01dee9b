#include "common/protocol/BrickLink.hpp"

#include <new>

#include "common/protocol/Packet.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap::protocol {
namespace {
bool samePath(const PathProgressMsg& a, const PathProgressMsg& b) {
  return a.pathId == b.pathId && a.reached == b.reached && a.state == b.state && a.at == b.at;
}
bool samePose(const Pose& a, const Pose& b) { return a.cell == b.cell && a.heading == b.heading; }
// A believed offset held to what StatusMsg carries.
int16_t clampOffset(int32_t mm) {
  constexpr int32_t kMax = StatusMsg::kMaxOffsetMm;
  return static_cast<int16_t>(mm < -kMax ? -kMax : (mm > kMax ? kMax : mm));
}
#ifndef NXTMAP_NO_START_SQUARING
// v / 10, rounded, held to int16_t's range.
int16_t tenths(int32_t v) {
  const int32_t t = v >= 0 ? (v + 5) / 10 : -((-v + 5) / 10);
  return static_cast<int16_t>(t > 32767 ? 32767 : (t < -32767 ? -32767 : t));
}
#endif
}  // namespace

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

bool BrickLink::transmit(uint32_t nowMs, const BrickReport& report, Frame& out, Scope scope) {
  nowMs_ = nowMs;
  LegoContext lego;
  lego.batteryMillivolts = report.batteryMillivolts;
  lego.sleepLimitMs = config_.sleepLimitMs;
  lego.motorsBusy = report.mode == BrickMode::Exploring || report.mode == BrickMode::Following;
  lego.firmwareMinor = kProtocolVersion;
  if (lego_.next(lego, *brick_, out)) return true;
  Payload p;
  if (helloReplyDue_) {
    helloReplyDue_ = false;
    HelloReplyMsg m;
    m.session = session_;
    m.mapEpoch = sync_.epoch();
    m.freshSession = freshSession_;
    m.gridWidthLog2 = sync_.widthLog2();
    m.gridHeightLog2 = sync_.heightLog2();
    m.geometry = config_.geometry;
    encodeHelloReply(m, p);
    return send(Op::HelloReply, false, p, out);
  }
  if (!connected_) return false;
  const int expired = sync_.expire(nowMs);
  if (expired > 0) {
    counters_.retransmits += static_cast<uint32_t>(expired);
    scanNow_ = true;
  }

  if (stateDue_) {  // after a Hello: pose, path and room once, whatever they are
    stateDue_ = false;
    posePending_ = pathPending_ = roomPending_ = true;
  }
  if (posePending_ || !samePose(lastPose_.pose, report.pose)) {
    posePending_ = false;
    lastPose_.pose = report.pose;
    encodePose(lastPose_, p);
    return send(Op::Pose, false, p, out);
  }
  if (pathPending_ || !samePath(lastPath_, report.path)) {
    pathPending_ = false;
    lastPath_ = report.path;
    encodePathProgress(lastPath_, p);
    return send(Op::PathProgress, false, p, out);
  }
  if (roomPending_ || lastRoom_ != report.roomId) {
    roomPending_ = false;
    lastRoom_ = report.roomId;
    encodeNewRoom(NewRoomMsg{report.roomId, report.roomEntry, report.fromRoom, report.roomOrigin, report.roomHeading},
                  p);
    return send(Op::NewRoom, false, p, out);
  }
  if (batteryDue_) {
    batteryDue_ = false;
    encodeBattery(BatteryMsg{report.batteryMillivolts}, p);
    return send(Op::Battery, false, p, out);
  }
  if (!statusSent_ || nowMs - lastStatusMs_ >= config_.statusPeriodMs) {
    // Every period: Status; every other period: Counters. Pose, path and room repeat with it, so a
    // lost report (e.g. "blocked", the new room's frame) is made good within one period on a bad link.
    statusSent_ = true;
    lastStatusMs_ = nowMs;
    posePending_ = pathPending_ = roomPending_ = true;
    countersPhase_ = !countersPhase_;
    countersDue_ = countersPhase_;
    exitsDue_ = report.exits != nullptr;
    readingsDue_ = report.readings != nullptr;
    StatusMsg s;
    s.mode = report.mode;
    s.pose = report.pose;
    s.offsetXMm = clampOffset(report.offsetXMm);
    s.offsetYMm = clampOffset(report.offsetYMm);
    s.batteryMillivolts = report.batteryMillivolts;
    s.mapEpoch = sync_.epoch();
    s.roomId = report.roomId;
    s.path = report.path;
    encodeStatus(s, p);
    return send(Op::Status, false, p, out);
  }
  if (countersDue_) {
    countersDue_ = false;
#ifndef NXTMAP_NO_START_SQUARING
    encodeCounters(CountersMsg{report.counters, counters_, tenths(report.wheelDriftUradPerM),
                               tenths(report.wheelTurnPpm)},
                   p);
#else
    encodeCounters(CountersMsg{report.counters, counters_}, p);  // the RAM-run image learns no wheels
#endif
    return send(Op::Counters, false, p, out);
  }
  if (exitsDue_ && report.exits != nullptr) {
    // The room's end is told once the PC holds all of its map: nothing pending, nothing in flight.
    exitsDue_ = false;
    RoomExitsMsg m = *report.exits;
    if (sync_.pending() || sync_.inFlight() > 0) m.end = ExplorerEnd::Running;
    encodeRoomExits(m, p);
    return send(Op::RoomExits, false, p, out);
  }
  if (readingsDue_ && report.readings != nullptr) {
    readingsDue_ = false;
    encodeReadings(*report.readings, p);
    return send(Op::Readings, false, p, out);
  }
  if (scope == Scope::All && (scanNow_ || nowMs - lastScanMs_ >= config_.deltaPeriodMs)) {
    lastScanMs_ = nowMs;
    const uint16_t seq = nextSeq(txSeq_);
    scanNow_ = sync_.buildDelta(seq, nowMs, p);
    if (scanNow_) {
      txSeq_ = seq;
      return send(Op::MapDelta, true, p, out);
    }
  }
  if (ackDue_) {
    p.size = 0;
    return send(Op::Ack, false, p, out);
  }
  return false;
}

}  // namespace nxtmap::protocol
