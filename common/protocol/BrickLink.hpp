#pragma once
#include <cstddef>
#include <cstdint>

#include "common/grid/RoomGrid.hpp"
#include "common/protocol/Command.hpp"
#include "common/protocol/FrameDecoder.hpp"
#include "common/protocol/Mailboxes.hpp"
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
  Counters counters;
  uint16_t batteryMillivolts = 0;
  uint16_t roomId = 0;
  Cell roomEntry{};
  uint16_t fromRoom = 0;  // the room the robot came from, and the new room's origin and +y in its frame
  Cell roomOrigin{};
  Dir roomHeading = Dir::North;
  PathProgressMsg path;
  // Mapping a house: the exits of the room being mapped (nullptr: not mapping a house). Its `end`
  // goes out as Running until the PC holds every cell of the room's map (see BrickLink::transmit).
  const RoomExitsMsg* exits = nullptr;
  // Mapping a house: the last standing scan and the room's start readings (nullptr: none), sent
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
//   link.receive(byte);                                  // from the UART, in any amount
//   while (link.nextCommand(cmd)) carryOut(cmd);         // each command exactly once
//   while (uartHasRoom() && link.transmit(now, report, frame)) uartSend(frame.bytes, frame.size);
//   on disconnect: link.linkLost();  on new room / restructuring: link.mapRestarted();
//
// It answers LEGO's GET_BATTERY_LEVEL, KEEP_ALIVE, MESSAGE_WRITE and MESSAGE_READ at any time,
// and nxtmap packets after the PC's Hello. No heap; all memory is inside the object plus the
// caller's shadow (see MapSync).
class BrickLink {
 public:
  static constexpr int kCommandQueue = 2;

  // `shadow`: packedBytes(grid capacity, 2) bytes, caller-owned, for MapSync.
  BrickLink(const RoomGrid& grid, uint8_t* shadow, const BrickLinkConfig& config);

  // One received byte; `nowMs` is the brick's millisecond clock.
  void receive(uint8_t byte);
  // The next command to carry out; false when none is waiting.
  bool nextCommand(Command& out);
  // The next frame to send, if any (LEGO replies first, then hello, pose, path, room, battery,
  // status, map deltas, a bare ack). Call until it returns false.
  bool transmit(uint32_t nowMs, const BrickReport& report, Frame& out);

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
  Mailboxes& mailboxes() { return boxes_; }

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
  Mailboxes boxes_;
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
  uint8_t legoPending_ = 0;      // opcode of a battery/keep-alive request to answer (0 = none)
  bool legoReplyReady_ = false;  // legoReply_ holds a mailbox reply to send
  Frame legoReply_;
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
