#pragma once
#include <cstddef>
#include <cstdint>

#include "common/protocol/LegoFormat.hpp"

// The radio link's wire format, shared by the brick, the emulator bridge and the PC.
//
// Every frame is the NXT's Bluetooth stream framing: a 2-byte little-endian length, then a
// telegram of that many bytes, laid out as LEGO's protocol has it: [type][opcode][...].
//
//  - LEGO direct and system commands (types 0x00 / 0x01 reply wanted, 0x80 / 0x81 no reply) and
//    their replies (type 0x02) follow LEGO's layout exactly (LegoFormat.hpp), so existing NXT tools
//    (nxt-python, NXC's BT tools) work. A telegram of a LEGO type is consumed whole by its length,
//    understood or not; an nxtmap packet is never read as one, nor the reverse.
//  - nxtmap packets use type kTypeNxtmap:
//      [0x4E][opcode][version][flags][seq u16][ack u16][ackMask u16][payload...][crc32 u32]
//    All multi-byte fields little-endian. crc32 (IEEE 802.3, reflected, as zlib's crc32) covers
//    every telegram byte before it. seq 0 = unreliable (never acknowledged, never deduplicated);
//    reliable packets carry seq 1..65535 (0 skipped on wrap) and are acknowledged by the peer's
//    ack/ackMask: ack = newest reliable seq received, bit i of ackMask = seq (ack - 1 - i) received.
namespace nxtmap::protocol {

// 3: Scan and Readings (a house's standing scan, start readings); 4: HelloReply carries the
// brick's range geometry (cell size, trusted range, sensor mount); 5: Counters carries the wheels'
// drift and turn error the robot has learnt; 6: Readings carries the standing scan only (no start readings);
// 7: Status tells where in its cell the robot is believed to stand; 8: Calibrate.
constexpr uint8_t kProtocolVersion = 8;

// Sizes (bytes). LEGO's Bluetooth input buffer holds 128 bytes per message.
constexpr size_t kLengthPrefix = 2;
constexpr size_t kMaxTelegram = 126;
constexpr size_t kMaxFrame = kLengthPrefix + kMaxTelegram;  // 128
constexpr size_t kPacketHeader = 10;
constexpr size_t kPacketTrailer = 4;                                           // crc32
constexpr size_t kMaxPayload = kMaxTelegram - kPacketHeader - kPacketTrailer;  // 112

// Telegram types (byte 0).
constexpr uint8_t kTypeDirect = 0x00;         // LEGO direct command, reply wanted
constexpr uint8_t kTypeSystem = 0x01;         // LEGO system command, reply wanted
constexpr uint8_t kTypeReply = 0x02;          // LEGO reply
constexpr uint8_t kTypeDirectNoReply = 0x80;  // LEGO direct command, no reply
constexpr uint8_t kTypeSystemNoReply = 0x81;  // LEGO system command, no reply
constexpr uint8_t kTypeNxtmap = 0x4E;         // 'N': an nxtmap packet

// nxtmap opcodes. PC -> brick:
enum class Op : uint8_t {
  Hello = 0x01,           // unreliable; HelloMsg
  Explore = 0x02,         // reliable command; ExploreMsg: start (or resume) exploring
  Stop = 0x03,            // reliable command, no payload: stop moving
  FollowPath = 0x04,      // reliable command; PathMsg
  RequestMap = 0x05,      // reliable command, no payload: send the whole map again (new epoch)
  MapChunk = 0x06,        // reliable command; MapChunkMsg (whole map PC -> brick, in chunks)
  Ack = 0x07,             // unreliable, no payload: carries only ack/ackMask
  BatteryRequest = 0x08,  // unreliable, no payload: answered by Battery
  SetPose = 0x09,         // reliable command; PoseMsg: the robot stands at this pose of the brick's map
                          // (sent after a MapChunk upload: the pose in the uploaded map's frame)
  GoTo = 0x0A,            // reliable command; GoToMsg: drive to a cell of the brick's map
  EnterRoom = 0x0B,       // reliable command; EnterRoomMsg: cross a doorway, start the room beyond it
  Scan = 0x0C,            // reliable command; ScanMsg: read the four sensors where the robot stands
  Calibrate = 0x0D,       // reliable command, no payload: measure the turns' error against the walls where the
                          // robot stands (TurnCalibration), keep it with what was learnt of the wheels, rest
  // brick -> PC:
  HelloReply = 0x41,    // unreliable; HelloReplyMsg
  Status = 0x42,        // unreliable, periodic; StatusMsg
  MapDelta = 0x43,      // reliable; MapDeltaMsg header + runs
  Pose = 0x44,          // unreliable, on change; PoseMsg
  PathProgress = 0x45,  // unreliable, on change and in Status; PathProgressMsg (also "blocked")
  NewRoom = 0x46,       // unreliable, on change and in Status; NewRoomMsg
  Battery = 0x47,       // unreliable; BatteryMsg
  Counters = 0x48,      // unreliable, periodic; CountersMsg
  RoomExits = 0x49,     // unreliable, periodic while mapping a house; RoomExitsMsg (absolute state)
  Readings = 0x4A,      // unreliable, periodic while mapping a house; ReadingsMsg (absolute state)
};

constexpr uint8_t kFlagReliable = 0x01;

}  // namespace nxtmap::protocol
