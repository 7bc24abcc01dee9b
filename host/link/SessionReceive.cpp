// Session's receiving side: the brick's frames decoded and taken in (its hello, acknowledgements of our commands,
// map deltas, statuses, counters, poses, path progress, rooms, exits, readings, battery; LEGO battery replies).
#include "host/link/Session.hpp"

#include "common/protocol/LegoCommands.hpp"

namespace nxtmap::link {

using namespace protocol;

void Session::receive(const uint8_t* data, size_t size, uint32_t nowMs) {
  counters_.bytesIn += size;
  Telegram t;
  for (size_t i = 0; i < size; ++i) {
    decoder_.push(data[i]);
    while (decoder_.pop(t)) handle(t, nowMs);
  }
}

void Session::handle(const Telegram& t, uint32_t nowMs) {
  ++counters_.packetsIn;
  if (t.type() == kTypeReply) {
    uint8_t status = 0;
    uint16_t mv = 0;
    if (decodeBatteryReply(t, status, mv) && status == kLegoOk) legoBattery_ = mv;
    return;
  }
  PacketView v;
  if (!parsePacket(t, v)) return;
  if (v.header.op == Op::HelloReply) return onHelloReply(v);
  if (!connected_ || v.header.version != kProtocolVersion) return;
  takeAcknowledgements(v.header);
  if (v.header.op == Op::MapDelta) return onMapDelta(v, t.size, nowMs);
  if (v.header.op == Op::Status) return onStatus(v);
  onReport(v);
}

void Session::onHelloReply(const PacketView& v) {
  // A HelloReply starts with its version in every protocol version; the rest of another
  // version's reply need not decode as ours.
  const uint8_t version = v.payloadSize > 0 ? v.payload[0] : v.header.version;
  if (version != kProtocolVersion) {
    error_ = "the brick speaks protocol version " + std::to_string(version) + ", this console " +
             std::to_string(kProtocolVersion) + ": flash the matching firmware";
    return;
  }
  HelloReplyMsg reply;
  if (!decodeHelloReply(v.payload, v.payloadSize, reply)) return;
  if (reply.session != config_.session || connected_) return;
  if (reply.freshSession) {
    map_.clear();  // the brick does not know us: whatever we hold may be stale
    received_.reset();
    roomId_.reset();  // nor its room counter (it may have restarted)
    roomEpoch_.reset();
    forgetTransmittedCommands();
  }
  hello_ = reply;
  connected_ = true;
  ++counters_.connects;
}

void Session::takeAcknowledgements(const PacketHeader& h) {
  // Stop-and-wait: only the front can be in flight.
  while (!outbox_.empty() && outbox_.front().sent && acknowledges(h.ack, h.ackMask, outbox_.front().seq)) {
    acknowledgedSeqs_.push_back(outbox_.front().seq);
    outbox_.pop_front();
    ++counters_.commandsAcknowledged;
  }
}

void Session::stashCopy() {
  roomExits_.reset();  // a room's end told before the new epoch is not the end of this copy
  if (map_.known() > 0) {
    stash_ = map_;  // a new epoch: keep the old copy until the room is known
    stashRoom_ = roomId_;
  }
}

void Session::onMapDelta(const PacketView& v, size_t frameBytes, uint32_t nowMs) {
  if (!v.header.reliable()) return;
  counters_.deltaBytes += kLengthPrefix + frameBytes;
  const uint64_t before = map_.changes();
  MapDeltaReader peek(v.payload, v.payloadSize);
  if (peek.validate() && map_.hasEpoch() && peek.header().epoch != map_.epoch()) stashCopy();
  if (map_.applyDelta(v.payload, v.payloadSize)) {
    ++counters_.deltasApplied;
    if (map_.changes() != before) lastMapChangeMs_ = nowMs;
  }
  // Acknowledged even when malformed: a resend would be the same bytes.
  received_.record(v.header.seq);
  ackOwed_ = true;
}

void Session::onStatus(const PacketView& v) {
  StatusMsg s;
  if (!decodeStatus(v.payload, v.payloadSize, s)) return;
  status_ = s;
  ++statuses_;
  noteRoom(s.roomId);
  setPoseFromBrick(s.pose);
  poseRoom_ = s.roomId;
  roomEpoch_ = s.mapEpoch;
  if (map_.hasEpoch() && s.mapEpoch != map_.epoch()) {
    // A new epoch whose first delta has not arrived yet: the old copy is void, and so is a room's end told
    // before it (the brick holds the end back until the new copy is whole).
    stashCopy();
    map_.clear();
  }
}

void Session::onReport(const PacketView& v) {
  switch (v.header.op) {
    case Op::Counters: {
      CountersMsg m;
      if (decodeCounters(v.payload, v.payloadSize, m)) {
        brickCounters_ = m;
        ++countersCount_;
      }
      break;
    }
    case Op::Pose: {
      PoseMsg m;
      if (decodePose(v.payload, v.payloadSize, m)) setPoseFromBrick(m.pose);
      break;
    }
    case Op::PathProgress: {
      PathProgressMsg m;
      if (decodePathProgress(v.payload, v.payloadSize, m)) path_ = m;
      break;
    }
    case Op::NewRoom: {
      NewRoomMsg m;
      if (decodeNewRoom(v.payload, v.payloadSize, m)) {
        room_ = m;
        noteRoom(m.roomId);
      }
      break;
    }
    case Op::RoomExits: {
      RoomExitsMsg m;
      if (decodeRoomExits(v.payload, v.payloadSize, m)) roomExits_ = m;
      break;
    }
    case Op::Readings: {
      ReadingsMsg m;
      if (decodeReadings(v.payload, v.payloadSize, m)) readings_ = m;
      break;
    }
    case Op::Battery: {
      BatteryMsg m;
      if (decodeBattery(v.payload, v.payloadSize, m)) battery_ = m.millivolts;
      break;
    }
    default: break;
  }
}

}  // namespace nxtmap::link
