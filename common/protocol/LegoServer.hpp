#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/LegoBrick.hpp"
#include "common/protocol/Mailboxes.hpp"
#include "common/protocol/Telegram.hpp"

namespace nxtmap::protocol {

// What answering a LEGO command needs from the brick at that moment.
struct LegoContext {
  uint16_t batteryMillivolts = 0;  // GET_BATTERY_LEVEL
  uint32_t sleepLimitMs = 0;       // KEEP_ALIVE (0: never sleeps)
  bool motorsBusy = false;         // exploring or following a path: motor commands are refused
  uint8_t firmwareMinor = 0;       // GET_FIRMWARE_VERSION's firmware minor (major 0: nxtmap)
};

// The brick's side of LEGO's direct and system commands. Commands are queued as they arrive and
// carried out in order, one reply each, when the link has room to send (next()): back-to-back
// requests each get their reply, in the order asked.
//
// Served (LegoFormat.hpp): PLAY_TONE, SET_OUTPUT_STATE, GET_OUTPUT_STATE, GET_INPUT_VALUES,
// MESSAGE_WRITE, RESET_MOTOR_POSITION, GET_BATTERY_LEVEL, STOP_SOUND_PLAYBACK, KEEP_ALIVE,
// MESSAGE_READ, GET_FIRMWARE_VERSION, SET_BRICK_NAME, GET_DEVICE_INFO. Any other command that wants
// a reply is answered kLegoUnknownCommand; a served one of the wrong size kLegoInsanePacket, with
// its reply's full layout zero-filled; one that wants no reply and is not served leaves no trace.
class LegoServer {
 public:
  // Queue bytes: each command takes its size + 1 (an unknown one 3). Room for the largest
  // (MESSAGE_WRITE, 63 bytes) is kept free while receiving (hasRoom()).
  static constexpr size_t kQueueBytes = 192;
  static constexpr size_t kLargestEntry = 1 + 4 + kLegoMaxMessage;

  LegoServer();

  // A telegram of a LEGO type as the decoder delivered it: queued, or dropped (replies, unserved
  // commands that want no reply; a full queue, counted in dropped()).
  void take(const Telegram& t);
  // Whether a command of any size can be queued now (the firmware reads bytes only then).
  bool hasRoom() const { return kQueueBytes - used_ >= kLargestEntry; }
  bool pending() const { return used_ > 0; }
  // Carries out queued commands in order until one has a reply: true with the reply in `out`.
  bool next(const LegoContext& ctx, LegoBrick& brick, Frame& out);
  // The link dropped: the commands not yet answered are forgotten (their client is gone).
  void forget() { head_ = used_ = 0; }

  Mailboxes& mailboxes() { return boxes_; }
  const char* name() const { return name_; }
  uint32_t dropped() const { return dropped_; }

 private:
  uint8_t at(size_t i) const { return ring_[(head_ + i) % kQueueBytes]; }
  void push(const uint8_t* bytes, size_t n);
  // Carries out one command; fills `reply` (a whole reply telegram) when one is due.
  void carryOut(const uint8_t* c, size_t n, bool wellFormed, const LegoContext& ctx, LegoBrick& brick, uint8_t* reply);
  uint8_t setOutputs(const uint8_t* c, const LegoContext& ctx, LegoBrick& brick);
  void setName(const uint8_t* c, size_t n);

  Mailboxes boxes_;
  char name_[kLegoNameChars + 1] = {};
  static constexpr uint8_t kMalformed = 0x80;  // entry header bit: a served opcode of the wrong size
  uint8_t ring_[kQueueBytes] = {};             // entries [n | kMalformed?][n command bytes], oldest at head_
  size_t head_ = 0, used_ = 0;
  uint32_t dropped_ = 0;
};

}  // namespace nxtmap::protocol
