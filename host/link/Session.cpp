#include "host/link/Session.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>

#include "common/protocol/LegoCommands.hpp"

namespace nxtmap::link {

using namespace protocol;

namespace {

// A command's bytes, as the brick's own decoder takes them; std::invalid_argument(`refused`) when that
// decoder would refuse them (the brick acknowledges a malformed command and never runs it).
template <class Msg, class Encode, class Decode>
Payload brickWillTake(const Msg& m, Encode encode, Decode decode, const char* refused) {
  Payload p;
  Msg back;
  if (encode(m, p) == 0 || !decode(p.bytes, p.size, back)) throw std::invalid_argument(refused);
  return p;
}

}  // namespace

Session::Session(const SessionConfig& config) : config_(config) {
  while (config_.session == 0) config_.session = std::random_device{}();
}

uint16_t Session::enqueue(Op op, const Payload& payload) {
  nextSeq_ = nextSeq(nextSeq_);
  Outgoing o{op, nextSeq_, payload};
  outbox_.push_back(o);
  return nextSeq_;
}

uint16_t Session::explore(const ExploreMsg& how) {
  return enqueue(Op::Explore, brickWillTake(how, encodeExplore, decodeExplore, "an Explore needs a known strategy"));
}

uint16_t Session::goTo(uint16_t goalId, Cell target) {
  return enqueue(Op::GoTo,
                 brickWillTake(GoToMsg{goalId, target}, encodeGoTo, decodeGoTo, "the goal's cell is out of range"));
}

uint16_t Session::enterRoom(const EnterRoomMsg& m) {
  return enqueue(Op::EnterRoom,
                 brickWillTake(m, encodeEnterRoom, decodeEnterRoom,
                               "the doorway is not one the brick can cross (1..32 cells wide, 1..8 deep, "
                               "entered by one step outward from the inside cell)"));
}
uint16_t Session::scan(uint16_t scanId) {
  return enqueue(Op::Scan, brickWillTake(ScanMsg{scanId}, encodeScan, decodeScan, "a scan's id is 1..65535"));
}
uint16_t Session::stop() { return enqueue(Op::Stop, Payload{}); }

uint16_t Session::calibrate() { return enqueue(Op::Calibrate, Payload{}); }
uint16_t Session::requestMap() { return enqueue(Op::RequestMap, Payload{}); }

uint16_t Session::followPath(const std::vector<Cell>& cells, uint16_t pathId) {
  if (cells.empty()) throw std::invalid_argument("a path needs at least one cell");
  if (cells.size() > kMaxPathCells) {
    throw std::invalid_argument("a path of " + std::to_string(cells.size()) + " cells is longer than " +
                                std::to_string(kMaxPathCells));
  }
  PathMsg m;
  m.pathId = pathId;
  for (const Cell c : cells) {
    if (!m.append(c)) throw std::invalid_argument("the path's cells must be 8-neighbours, one after another");
  }
  return enqueue(Op::FollowPath, brickWillTake(m, encodePath, decodePath, "the path's cells are out of range"));
}

void Session::uploadMap(const Bounds& window, const std::vector<CellState>& rowMajor, uint16_t transferId) {
  const size_t total = static_cast<size_t>(window.width()) * static_cast<size_t>(window.height());
  if (window.empty() || window.width() > 128 || window.height() > 128 || rowMajor.size() != total) {
    throw std::invalid_argument("a map to upload must be 1..128 cells on each side, one state per cell");
  }
  // A damaged link loses long packets far more often than short ones (each byte is a chance): once
  // commands have needed resending or noise was skipped, the map goes in short chunks.
  const bool damaged = counters_.commandRetries > 0 || decoder_.counters().skipped > 0;
  const size_t per = damaged ? kDamagedLinkChunkCells : kChunkCells;
  const uint16_t chunks = static_cast<uint16_t>((total + per - 1) / per);
  for (uint16_t k = 0; k < chunks; ++k) {
    MapChunkMsg m;
    m.transferId = transferId;
    m.chunkIndex = k;
    m.chunkCount = chunks;
    m.window = window;
    m.offset = static_cast<uint16_t>(k * per);
    m.count = static_cast<uint16_t>(std::min<size_t>(per, total - m.offset));
    for (uint16_t i = 0; i < m.count; ++i) m.setState(i, rowMajor[m.offset + i]);
    enqueue(Op::MapChunk, brickWillTake(m, encodeMapChunk, decodeMapChunk, "the map's window is out of range"));
  }
}

uint16_t Session::setPose(const Pose& pose) {
  return enqueue(Op::SetPose, brickWillTake(PoseMsg{pose}, encodePose, decodePose, "the pose's cell is out of range"));
}

std::vector<RoomChange> Session::takeRoomChanges() {
  std::vector<RoomChange> out;
  out.swap(roomChanges_);
  return out;
}

std::vector<UnconfirmedCommand> Session::takeUnconfirmed() {
  std::vector<UnconfirmedCommand> out;
  out.swap(unconfirmed_);
  return out;
}

// The brick answered as a fresh session: it no longer knows which of our sequence numbers it ran.
// A command that went out before may have run; sending it again could run it twice.
void Session::forgetTransmittedCommands() {
  while (!outbox_.empty() && outbox_.front().transmitted) {
    unconfirmed_.push_back(UnconfirmedCommand{outbox_.front().op, outbox_.front().seq});
    outbox_.pop_front();
    ++counters_.commandsUnconfirmed;
  }
}

void Session::setPoseFromBrick(const Pose& p) {
  if (pose_ && pose_->cell == p.cell && pose_->heading == p.heading) return;
  posePrevious_ = pose_;
  pose_ = p;
  poseRoom_.reset();
}

void Session::noteRoom(uint16_t id) {
  if (!roomId_) {
    roomId_ = id;
    return;
  }
  if (*roomId_ == id) return;
  RoomChange c;
  c.fromRoom = *roomId_;
  c.toRoom = id;
  // The old room's map: the copy of the epoch the last Status from that room named, which a
  // new epoch's first delta may already have moved to the stash (then the copy is the new room's).
  // A copy already of a later epoch than that Status named holds the new room's first cells, even
  // when the old room had nothing to stash: it stays (those cells were acknowledged and are not sent
  // again).
  const bool copyIsNewer = roomEpoch_ && map_.hasEpoch() && map_.epoch() != *roomEpoch_;
  bool leftIsCopy = true;
  if (roomEpoch_ && map_.hasEpoch() && map_.epoch() == *roomEpoch_) {
    c.left = map_;
  } else if (stashRoom_ == *roomId_ && stash_.known() > 0) {
    c.left = stash_;
    leftIsCopy = false;
  } else if (copyIsNewer) {
    leftIsCopy = false;  // the old room left nothing known
  } else {
    c.left = map_;
  }
  // The brick reports the new room's start pose (0,0 facing +y) before the room itself: a pose
  // not confirmed in the old room by a Status that equals that start is the new room's.
  const bool startPose = pose_ && pose_->cell == Cell{0, 0} && pose_->heading == Dir::North;
  if (poseRoom_ == *roomId_ || !startPose)
    c.lastPose = pose_;
  else
    c.lastPose = posePrevious_;
  roomChanges_.push_back(std::move(c));
  roomId_ = id;
  if (leftIsCopy) map_.clear();  // the new room's map comes as a new epoch
  stash_.clear();
  stashRoom_.reset();
  poseRoom_.reset();
  roomEpoch_.reset();
}

bool Session::acknowledged(uint16_t seq) const {
  return std::find(acknowledgedSeqs_.begin(), acknowledgedSeqs_.end(), seq) != acknowledgedSeqs_.end();
}

void Session::linkLost() {
  connected_ = false;
  helloSent_ = false;
  decoder_.reset();
  for (Outgoing& o : outbox_) o.sent = false;  // will go again (same seq) after the Hello
}

void Session::append(std::vector<uint8_t>& out, Op op, uint16_t seq, const Payload& payload) {
  PacketHeader h;
  h.op = op;
  h.flags = seq != 0 ? kFlagReliable : 0;
  h.seq = seq;
  h.ack = received_.ack();
  h.ackMask = received_.ackMask();
  Frame f;
  if (!encodePacket(h, payload.bytes, payload.size, f)) return;
  out.insert(out.end(), f.bytes, f.bytes + f.size);
  ackOwed_ = false;
}

std::vector<uint8_t> Session::transmit(uint32_t nowMs) {
  std::vector<uint8_t> out;
  if (legoBatteryRequested_) {
    legoBatteryRequested_ = false;
    Frame f;
    encodeGetBatteryLevel(f);
    out.insert(out.end(), f.bytes, f.bytes + f.size);
  }
  if (!connected_) {
    if (!helloSent_ || nowMs - helloMs_ >= config_.helloRetryMs) {
      helloSent_ = true;
      helloMs_ = nowMs;
      Payload p;
      encodeHello(HelloMsg{kProtocolVersion, config_.session, !map_.hasEpoch()}, p);
      append(out, Op::Hello, 0, p);
    }
  } else {
    if (batteryRequested_) {
      batteryRequested_ = false;
      append(out, Op::BatteryRequest, 0, Payload{});
    }
    if (!outbox_.empty()) {
      Outgoing& o = outbox_.front();
      if (!o.sent || nowMs - o.sentMs >= config_.commandRetryMs) {
        if (o.sent)
          ++counters_.commandRetries;
        else
          ++counters_.commandsSent;
        o.sent = true;
        o.transmitted = true;
        o.sentMs = nowMs;
        append(out, o.op, o.seq, o.payload);
      }
    }
    if (ackOwed_) {
      // Acks are small and the way back is idle: two copies, so one damaged byte does not
      // cost the brick a retransmission.
      append(out, Op::Ack, 0, Payload{});
      append(out, Op::Ack, 0, Payload{});
    }
  }
  counters_.bytesOut += out.size();
  return out;
}

}  // namespace nxtmap::link
