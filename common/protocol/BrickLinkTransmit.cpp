// BrickLink's sending side: what goes out next, the LEGO replies first, then the hello's reply, acks, the path's
// and the pose's changes, the counters and the map's deltas (each only when due), from one BrickReport.
#include "common/protocol/BrickLink.hpp"

#include "common/protocol/Packet.hpp"

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
    encodeCounters(
        CountersMsg{report.counters, counters_, tenths(report.wheelDriftUradPerM), tenths(report.wheelTurnPpm)}, p);
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
