// Session: the PC's end of the radio link, as a state machine without I/O. Feed it received
// bytes and the time; ask it for bytes to send. It says Hello until the brick answers, keeps
// the MirrorMap equal to the brick's grid (applying and acknowledging map deltas), sends
// commands one at a time until each is acknowledged (the same sequence number every time, so
// the brick runs it once), and starts over with Hello after linkLost().
//
// A command runs at most once, and exactly once while the brick knows this session: the
// session id stays the same for the Session's life (one console run), so after a reconnect the
// brick still holds the sequence numbers it ran and a resent command whose acknowledgement was
// lost is only acknowledged. A brick that answers the Hello as a fresh session has forgotten them
// (it restarted, or another console talked to it in between): a command sent before and never
// acknowledged may or may not have run, and is not sent again but reported (takeUnconfirmed()).
#pragma once
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/Messages.hpp"
#include "common/protocol/Packet.hpp"
#include "common/protocol/SeqWindow.hpp"
#include "host/link/MirrorMap.hpp"

namespace nxtmap::link {

struct SessionConfig {
  uint32_t session = 0;         // 0: pick a random one
  uint32_t helloRetryMs = 250;  // Hello again until the brick answers
  uint32_t commandRetryMs = 250;
};

// Figures of one session, for status and benchmarks.
struct SessionCounters {
  uint64_t bytesIn = 0, bytesOut = 0;
  uint64_t packetsIn = 0;
  uint64_t deltasApplied = 0;
  uint64_t deltaBytes = 0;      // wire bytes of the map deltas received (frames whole)
  uint64_t commandsSent = 0;    // first transmissions
  uint64_t commandRetries = 0;  // repeated transmissions
  uint64_t commandsAcknowledged = 0;
  uint64_t connects = 0;             // HelloReplies that opened the session
  uint64_t commandsUnconfirmed = 0;  // sent, never acknowledged, and the brick forgot the session
};

// A command that was sent but never acknowledged when the brick answered as a fresh session: it
// may have run before the brick forgot it; it is not sent again.
struct UnconfirmedCommand {
  protocol::Op op;
  uint16_t seq;
};

// The brick went into another room (NewRoom, or a Status with another room id): the room it
// left, as the PC held it when the change became known.
struct RoomChange {
  uint16_t fromRoom = 0, toRoom = 0;
  MirrorMap left;                // the map of the room it left (its frame)
  std::optional<Pose> lastPose;  // where the robot stood last in that room, when known
};

class Session {
 public:
  // Cells per MapChunk on a link that damages bytes (a frame of about 40 bytes; kChunkCells otherwise).
  static constexpr size_t kDamagedLinkChunkCells = 48;
  explicit Session(const SessionConfig& config = {});

  void receive(const uint8_t* data, size_t size, uint32_t nowMs);
  // Bytes to send now (may be empty).
  std::vector<uint8_t> transmit(uint32_t nowMs);
  // The transport dropped: bytes in flight are gone; say Hello again.
  void linkLost();

  // Commands, queued and sent in order. Each returns its sequence number. A command the brick's own
  // decoder would refuse is not queued: std::invalid_argument says why.
  // Explore: the frontier explorer, not confined, unless `how` says otherwise.
  uint16_t explore(const protocol::ExploreMsg& how = protocol::ExploreMsg{});
  // Mapping a house: drive to a cell of the brick's map (progress as PathProgress with pathId =
  // goalId); cross a doorway and map the room beyond it. Throw std::invalid_argument when the
  // message cannot be encoded.
  uint16_t goTo(uint16_t goalId, Cell target);
  uint16_t enterRoom(const protocol::EnterRoomMsg& m);
  // A standing scan (the brick's Readings echo `scanId`, 1..65535, once it is done). Throws
  // std::invalid_argument for scanId 0.
  uint16_t scan(uint16_t scanId);
  uint16_t stop();
  // Measure the turns' error where the robot stands (Op::Calibrate); the result comes in Counters.
  uint16_t calibrate();
  // A path of 8-neighbour cells (cell 0 = the robot's cell), at most kMaxPathCells cells.
  // Throws std::invalid_argument for an empty, too long or broken path.
  uint16_t followPath(const std::vector<Cell>& cells, uint16_t pathId);
  // Asks for the whole map again (the brick starts a new epoch; the copy is rebuilt).
  uint16_t requestMap();
  // Sends a whole map to the brick in chunks (window + row-major states).
  void uploadMap(const Bounds& window, const std::vector<CellState>& rowMajor, uint16_t transferId);
  // Tells the brick where the robot stands on the map it holds (after uploadMap: in that map's
  // frame). Returns the command's sequence number.
  uint16_t setPose(const Pose& pose);
  void requestBattery() { batteryRequested_ = true; }
  // LEGO GET_BATTERY_LEVEL, as any NXT tool sends it (answer in legoBatteryMillivolts()).
  void requestLegoBattery() { legoBatteryRequested_ = true; }

  bool connected() const { return connected_; }
  // Whether every queued command has been acknowledged.
  bool commandsDone() const { return outbox_.empty(); }
  bool acknowledged(uint16_t seq) const;
  const std::string& error() const { return error_; }  // e.g. a protocol version mismatch

  const MirrorMap& map() const { return map_; }
  const std::optional<protocol::StatusMsg>& status() const { return status_; }
  // Statuses received so far (to tell a status sent after some event from an older one).
  uint64_t statusesReceived() const { return statuses_; }
  // Counters received so far (the same for the wheels the brick reports).
  uint64_t countersReceived() const { return countersCount_; }
  const std::optional<protocol::CountersMsg>& brickCounters() const { return brickCounters_; }
  const std::optional<Pose>& pose() const { return pose_; }
  const std::optional<protocol::PathProgressMsg>& pathProgress() const { return path_; }
  const std::optional<protocol::NewRoomMsg>& room() const { return room_; }
  // The exits of the room the brick maps as part of a house, as last reported in the map epoch the
  // copy holds (forgotten when a new epoch begins: its end then waits for the new copy to be whole).
  const std::optional<protocol::RoomExitsMsg>& roomExits() const { return roomExits_; }
  // The last standing scan of a robot mapping a house, as last reported.
  const std::optional<protocol::ReadingsMsg>& readings() const { return readings_; }
  // The brick's room counter as last reported (none before the first report).
  const std::optional<uint16_t>& roomId() const { return roomId_; }
  // Room changes since the last call, oldest first.
  std::vector<RoomChange> takeRoomChanges();
  // Commands given up since the last call because the brick forgot this session (see above).
  std::vector<UnconfirmedCommand> takeUnconfirmed();
  const std::optional<uint16_t>& batteryMillivolts() const { return battery_; }
  const std::optional<uint16_t>& legoBatteryMillivolts() const { return legoBattery_; }
  const std::optional<protocol::HelloReplyMsg>& hello() const { return hello_; }
  const SessionCounters& counters() const { return counters_; }
  const protocol::DecoderCounters& decoderCounters() const { return decoder_.counters(); }
  uint32_t sessionId() const { return config_.session; }
  // Time (ms, the caller's clock) of the last map delta that changed the copy.
  uint32_t lastMapChangeMs() const { return lastMapChangeMs_; }

 private:
  struct Outgoing {
    protocol::Op op;
    uint16_t seq;
    protocol::Payload payload;
    bool sent = false;         // on the current connection
    bool transmitted = false;  // on any connection: it may have reached the brick
    uint32_t sentMs = 0;
  };
  uint16_t enqueue(protocol::Op op, const protocol::Payload& payload);
  void handle(const protocol::Telegram& t, uint32_t nowMs);  // one frame from the brick (SessionReceive.cpp)
  void onHelloReply(const protocol::PacketView& v);
  void takeAcknowledgements(const protocol::PacketHeader& h);  // our commands the header acknowledges
  void onMapDelta(const protocol::PacketView& v, size_t frameBytes, uint32_t nowMs);
  void onStatus(const protocol::PacketView& v);
  void onReport(const protocol::PacketView& v);  // counters, pose, path, room, exits, readings, battery
  // A new map epoch: the copy held so far kept aside (if any) until its room is known, its room's end void.
  void stashCopy();
  void append(std::vector<uint8_t>& out, protocol::Op op, uint16_t seq, const protocol::Payload& payload);
  void noteRoom(uint16_t id);
  void setPoseFromBrick(const Pose& p);
  void forgetTransmittedCommands();

  SessionConfig config_;
  protocol::FrameDecoder decoder_;
  protocol::SeqWindow received_;  // the brick's reliable seqs (map deltas)
  MirrorMap map_;
  std::deque<Outgoing> outbox_;
  uint16_t nextSeq_ = 0;
  bool connected_ = false;
  bool ackOwed_ = false;
  bool batteryRequested_ = false;
  bool legoBatteryRequested_ = false;
  bool helloSent_ = false;
  uint32_t helloMs_ = 0;
  std::string error_;
  std::optional<protocol::StatusMsg> status_;
  std::optional<protocol::CountersMsg> brickCounters_;
  std::optional<Pose> pose_;
  std::optional<Pose> posePrevious_;  // the pose before the last change
  std::optional<uint16_t> poseRoom_;  // the room a Status confirmed pose_ in (none: unconfirmed)
  std::optional<uint16_t> roomId_;
  std::optional<uint16_t> roomEpoch_;  // the map epoch the last Status of roomId_ named
  std::vector<RoomChange> roomChanges_;
  // The map as it was before the last epoch restart, and the room the brick was in then: a
  // new-room delta may overtake the (unreliable) NewRoom message.
  MirrorMap stash_;
  std::optional<uint16_t> stashRoom_;
  std::optional<protocol::PathProgressMsg> path_;
  std::optional<protocol::NewRoomMsg> room_;
  std::optional<protocol::RoomExitsMsg> roomExits_;
  std::optional<protocol::ReadingsMsg> readings_;
  uint64_t statuses_ = 0;
  uint64_t countersCount_ = 0;
  std::optional<uint16_t> battery_;
  std::optional<uint16_t> legoBattery_;
  std::optional<protocol::HelloReplyMsg> hello_;
  SessionCounters counters_;
  uint32_t lastMapChangeMs_ = 0;
  std::vector<uint16_t> acknowledgedSeqs_;
  std::vector<UnconfirmedCommand> unconfirmed_;
};

}  // namespace nxtmap::link
