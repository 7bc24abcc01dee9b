#pragma once
#include <cstddef>
#include <cstdint>

#include "common/grid/RoomGrid.hpp"
#include "common/protocol/Command.hpp"
#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/LegoBrick.hpp"
#include "common/protocol/LegoServer.hpp"
#include "common/protocol/MapSync.hpp"
#include "common/protocol/Packet.hpp"
#include "common/protocol/Messages.hpp"
#include "common/protocol/SeqWindow.hpp"
#include "common/protocol/Telegram.hpp"

namespace nxtmap::protocol {

// What the firmware is doing now; BrickLink reads it when it builds outgoing packets.
struct BrickReport {
  BrickMode mode = BrickMode::Idle;
  Pose pose;
  int32_t offsetXMm = 0, offsetYMm = 0;  // the robot's centre from pose.cell's centre, mm (StatusMsg)
  Counters counters;
  uint16_t batteryMillivolts = 0;
  // What the robot has learnt of its wheels (WheelCalibration): drift urad/m, turn error ppm.
  int32_t wheelDriftUradPerM = 0;
  int32_t wheelTurnPpm = 0;
  uint16_t roomId = 0;
  Cell roomEntry{};
  uint16_t fromRoom = 0;  // the room the robot came from, and the new room's origin and +y in its frame
  Cell roomOrigin{};
  Dir roomHeading = Dir::North;
  PathProgressMsg path;
  // Mapping a house: the exits of the room being mapped (nullptr: not mapping a house). Its `end`
  // goes out as Running until the PC holds every cell of the room's map (see BrickLink::transmit).
  const RoomExitsMsg* exits = nullptr;
  // Mapping a house: the last standing scan (nullptr: none), sent
  // every status period after the exits.
  const ReadingsMsg* readings = nullptr;
};

struct BrickLinkConfig {
  uint32_t retransmitMs =
      250;  // longest wait for a map delta's ack before it is sent again (adapts down to the round trip)
  uint32_t statusPeriodMs = 500;  // Status every this often while a PC is connected
  uint32_t sleepLimitMs = 0;      // KEEP_ALIVE answer (0 = the brick never sleeps)
  uint32_t deltaPeriodMs = 20;    // look for changed cells this often (a scan of the grid; batches changes)
  // How the brick's sensors read (rangeGeometryMsgOf its explorer's geometry), told to the PC in HelloReply.
  RangeGeometryMsg geometry{};
};

// The brick's end of the radio link: the one object the firmware (and the emulator's stand-ins)
// talk to. Feed it received bytes, take commands, and ask it for frames to send:
//
//   link.attach(legoBrick);                              // once: outputs, inputs, speaker (LegoBrick)
//   while (link.readyToReceive() && uartRead(byte)) link.receive(byte);
//   while (link.nextCommand(cmd)) carryOut(cmd);         // each command exactly once
//   while (uartHasRoom() && link.transmit(now, report, frame)) uartSend(frame.bytes, frame.size);
//   on disconnect: link.linkLost();  on new room / restructuring: link.mapRestarted();
//
// It answers LEGO's direct and system commands at any time (LegoServer: in order, one reply each,
// before any frame of its own), and nxtmap packets after the PC's Hello. No heap; all memory is
// inside the object plus the caller's shadow (see MapSync).
class BrickLink {
 public:
  static constexpr int kCommandQueue = 2;

  // `shadow`: packedBytes(grid capacity, 2) bytes, caller-owned, for MapSync.
  BrickLink(const RoomGrid& grid, uint8_t* shadow, const BrickLinkConfig& config);

  // Where LEGO's commands read and drive the brick (the default: nothing attached). `brick`
  // outlives the link.
  void attach(LegoBrick& brick) { brick_ = &brick; }
  // One received byte.
  void receive(uint8_t byte);
  // Whether any telegram the next bytes complete can be queued: the firmware leaves bytes in the
  // UART (its flow control holds the sender) while LEGO commands wait for their replies.
  bool readyToReceive() const { return lego_.hasRoom(); }
  // A LEGO reply or a HelloReply is waiting: worth sending without waiting for the radio period.
  bool replyDue() const { return lego_.pending() || helloReplyDue_; }
  // The next command to carry out; false when none is waiting.
  bool nextCommand(Command& out);
  // What a transmit() may build: everything, or all but map deltas (scanning the grid for changed
  // cells costs ~10 ms on the brick: not while the wheels are driven).
  enum class Scope : uint8_t { All, NoMapScan };
  // The next frame to send, if any (LEGO replies first, then hello, pose, path, room, battery,
  // status, map deltas, a bare ack). Call until it returns false.
  bool transmit(uint32_t nowMs, const BrickReport& report, Frame& out, Scope scope = Scope::All);

  // The radio connection dropped: the PC must say Hello again; deltas in flight are resent.
  void linkLost();
  // The grid was cleared or restructured (new room, end of mapping): the PC gets it all again.
  void mapRestarted() {
    sync_.restart();
    scanNow_ = true;
  }

  bool connected() const { return connected_; }
  uint16_t mapEpoch() const { return sync_.epoch(); }
  const LinkCounters& counters() const { return counters_; }
  const MapSync& mapSync() const { return sync_; }
  Mailboxes& mailboxes() { return lego_.mailboxes(); }
  const LegoServer& lego() const { return lego_; }

 private:
  void handle(const Telegram& t);
  void handlePacket(const Telegram& t);
  void handleHello(const uint8_t* p, size_t n);
  void handleCommand(const PacketHeader& h, const uint8_t* p, size_t n);
  bool send(Op op, bool reliable, const Payload& payload, Frame& out);

  BrickLinkConfig config_;
  FrameDecoder decoder_;
  SeqWindow commands_;  // the PC's reliable seqs seen: no command runs twice
  MapSync sync_;
  LegoServer lego_;
  NoLegoBrick noBrick_;
  LegoBrick* brick_ = &noBrick_;
  LinkCounters counters_;

  Command queue_[kCommandQueue];
  uint8_t queueFirst_ = 0, queueCount_ = 0;

  bool hasSession_ = false;
  uint32_t session_ = 0;
  bool freshSession_ = false;  // no packet but Hello from this session yet
  bool connected_ = false;
  bool helloReplyDue_ = false;
  bool batteryDue_ = false;
  bool ackDue_ = false;
  uint16_t txSeq_ = 0;
  uint32_t nowMs_ = 0;   // the clock at the last transmit() (receive() has none)
  bool scanNow_ = true;  // the last scan filled a delta: look again at once
  uint32_t lastScanMs_ = 0;
  bool statusSent_ = false;
  bool countersDue_ = false, countersPhase_ = false;
  bool exitsDue_ = false;     // RoomExits, every status period while mapping a house
  bool readingsDue_ = false;  // Readings, likewise
  uint32_t lastStatusMs_ = 0;
  bool stateDue_ = false;
  bool posePending_ = false, pathPending_ = false, roomPending_ = false;
  PoseMsg lastPose_;
  PathProgressMsg lastPath_;
  uint16_t lastRoom_ = 0;
};

static_assert(sizeof(BrickLink) <= 2560, "the brick's link: <= 2.5 KiB besides the 1 KiB shadow");

}  // namespace nxtmap::protocol
