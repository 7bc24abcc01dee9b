#pragma once
#include <cstddef>
#include <cstdint>

#include "common/explore/Counters.hpp"
#include "common/explore/Pose.hpp"
#include "common/grid/Cell.hpp"
#include "common/grid/CellState.hpp"
#include "common/protocol/HouseMessages.hpp"
#include "common/protocol/MapDelta.hpp"
#include "common/protocol/Payload.hpp"
#include "common/protocol/WireFormat.hpp"
#include "common/sensing/RangeGeometry.hpp"

// The payloads of nxtmap packets, each with an encoder and a validating decoder, both driven by
// one list of the message's fields (its Layout, FieldIo.hpp). Encoders write explicit
// little-endian fields, whatever their values, and return the payload size (0 = does not fit, or
// an array count out of range). Decoders read every field, check every range, and return false
// (leaving `out` unspecified but harmless) for anything malformed: truncated, trailing bytes,
// out-of-range enum or coordinate. The house messages (NewRoom among them) are in
// HouseMessages.hpp, MapDelta in MapDelta.hpp.
namespace nxtmap::protocol {

// ---- PC -> brick -------------------------------------------------------------------------

// Hello: opens (or re-opens after a reconnect) a session.
struct HelloMsg {
  uint8_t version = kProtocolVersion;
  uint32_t session = 0;  // chosen by the PC once per console run; a new value resets duplicate tracking
  bool wantMap = false;  // the PC has no copy of the map: send all of it (new epoch)
};
size_t encodeHello(const HelloMsg& m, Payload& out);
bool decodeHello(const uint8_t* p, size_t n, HelloMsg& out);

// FollowPath: a list of cells, each an 8-neighbour of the one before; cell 0 is where the robot
// stands. Encoded as the start cell and 4-bit moves (0 = N (+y), 1 = NE, 2 = E (+x), ... 7 = NW).
constexpr uint16_t kMaxPathCells = 128;
struct PathMsg {
  uint16_t pathId = 0;
  uint16_t count = 0;  // cells, 1..kMaxPathCells
  Cell start{};
  uint8_t moves[(kMaxPathCells - 1 + 1) / 2] = {};  // nibble i = move from cell i to cell i+1

  // Cell i of the path (0 <= i < count); walks the moves, O(i).
  Cell cellAt(uint16_t i) const;
  // Appends a cell; false when full or not an 8-neighbour of the last one.
  bool append(Cell c);
};
size_t encodePath(const PathMsg& m, Payload& out);
bool decodePath(const uint8_t* p, size_t n, PathMsg& out);

// MapChunk: part of a whole map sent PC -> brick. The map is the window's cells in row-major
// order from (minX, minY), 2 bits each (CellState), split into chunks of at most kChunkCells.
constexpr uint16_t kChunkCells = 368;
struct MapChunkMsg {
  uint16_t transferId = 0;
  uint16_t chunkIndex = 0;
  uint16_t chunkCount = 0;
  Bounds window{};      // the whole map's window (non-empty, at most 128 x 128)
  uint16_t offset = 0;  // first cell of this chunk, row-major in the window
  uint16_t count = 0;   // cells in this chunk, 1..kChunkCells
  uint8_t states[(kChunkCells + 3) / 4] = {};

  CellState state(uint16_t i) const { return static_cast<CellState>((states[i / 4] >> (2 * (i % 4))) & 3u); }
  void setState(uint16_t i, CellState s);
  // The map cell of chunk cell i.
  Cell cellOf(uint16_t i) const;
};
size_t encodeMapChunk(const MapChunkMsg& m, Payload& out);
bool decodeMapChunk(const uint8_t* p, size_t n, MapChunkMsg& out);

// ---- brick -> PC -------------------------------------------------------------------------

// How the brick's range sensors read (its explorer's RangeGeometry), one byte each, in whole
// centimetres: cellCm 1..255 (the simulator's worlds go up to 169 cm cells), 0 <= minCm < maxCm
// (maxCm <= 255: ranges up to 2.54 m), mountCm 0..50, sureCm 0 (= up to maxCm) or minCm..maxCm.
// The defaults are RangeGeometry{}'s (the published robot: 10 cm cells, 5 cm .. 1 m, centred).
struct RangeGeometryMsg {
  uint8_t cellCm = static_cast<uint8_t>(RangeGeometry{}.cellCm);
  uint8_t minCm = static_cast<uint8_t>(RangeGeometry{}.minCm);
  uint8_t maxCm = static_cast<uint8_t>(RangeGeometry{}.maxCm);
  uint8_t mountCm = static_cast<uint8_t>(RangeGeometry{}.mountCm);
  uint8_t sureCm = static_cast<uint8_t>(RangeGeometry{}.sureCm);
};
// The two forms, converted in one place. A geometry outside the wire's ranges is the brick's
// configuration error; its HelloReply is then refused by the PC.
constexpr RangeGeometryMsg rangeGeometryMsgOf(const RangeGeometry& g) {
  return RangeGeometryMsg{static_cast<uint8_t>(g.cellCm), static_cast<uint8_t>(g.minCm), static_cast<uint8_t>(g.maxCm),
                          static_cast<uint8_t>(g.mountCm), static_cast<uint8_t>(g.sureCm)};
}
constexpr RangeGeometry rangeGeometryOf(const RangeGeometryMsg& m) {
  RangeGeometry g;
  g.cellCm = m.cellCm;
  g.minCm = m.minCm;
  g.maxCm = m.maxCm;
  g.mountCm = m.mountCm;
  g.sureCm = m.sureCm;
  return g;
}

struct HelloReplyMsg {
  uint8_t version = kProtocolVersion;
  uint32_t session = 0;       // the PC's session, echoed
  uint8_t gridWidthLog2 = 6;  // brick grid capacity: 64 x 64
  uint8_t gridHeightLog2 = 6;
  uint16_t mapEpoch = 0;
  uint16_t maxPathCells = kMaxPathCells;
  // The session is new to the brick (it restarted, or another PC's session came between): the
  // PC clears its copy, and does not resend a command it sent before (it may have run).
  bool freshSession = false;
  RangeGeometryMsg geometry;  // how the brick's sensors read: the PC plans and matches scans with it
};
size_t encodeHelloReply(const HelloReplyMsg& m, Payload& out);
bool decodeHelloReply(const uint8_t* p, size_t n, HelloReplyMsg& out);

struct PoseMsg {
  Pose pose;
};
size_t encodePose(const PoseMsg& m, Payload& out);
bool decodePose(const uint8_t* p, size_t n, PoseMsg& out);

// Where the robot is on the last path it was given; Blocked = an obstacle stopped it at `at`
// (the cell it could not enter); the PC replans.
enum class PathState : uint8_t { None = 0, Following = 1, Reached = 2, Blocked = 3, Aborted = 4 };
struct PathProgressMsg {
  uint16_t pathId = 0;
  uint16_t reached = 0;  // index of the last path cell reached
  PathState state = PathState::None;
  Cell at{};
};
size_t encodePathProgress(const PathProgressMsg& m, Payload& out);
bool decodePathProgress(const uint8_t* p, size_t n, PathProgressMsg& out);

struct BatteryMsg {
  uint16_t millivolts = 0;
};
size_t encodeBattery(const BatteryMsg& m, Payload& out);
bool decodeBattery(const uint8_t* p, size_t n, BatteryMsg& out);

// What the brick is doing.
enum class BrickMode : uint8_t { Idle = 0, Exploring = 1, Following = 2, Done = 3, Fault = 4 };

// Link figures kept by the brick.
struct LinkCounters {
  uint32_t telegramsIn = 0;   // valid telegrams received
  uint32_t bytesSkipped = 0;  // noise bytes thrown away by the decoder
  uint32_t commandsRun = 0;   // commands handed to the firmware (each exactly once)
  uint32_t duplicates = 0;    // reliable commands received again and not run again
  uint32_t retransmits = 0;   // map deltas that timed out (their cells are sent again)
};

// What the brick is doing, small enough to get through a bad link often (25 bytes).
struct StatusMsg {
  static constexpr int16_t kMaxOffsetMm = 1000;
  BrickMode mode = BrickMode::Idle;
  Pose pose;
  uint16_t batteryMillivolts = 0;
  uint16_t mapEpoch = 0;
  uint16_t roomId = 0;
  PathProgressMsg path;
  // Where the robot's centre is believed to be from the centre of pose.cell: mm along the explorer's x (east) and
  // y (north), |.| <= kMaxOffsetMm; 0, 0 before the explorer starts (and on the RAM-run image, which keeps none).
  int16_t offsetXMm = 0;
  int16_t offsetYMm = 0;
};
size_t encodeStatus(const StatusMsg& m, Payload& out);
bool decodeStatus(const uint8_t* p, size_t n, StatusMsg& out);

// The explorer's and the link's counters and what the robot has learnt of its wheels (44 bytes), sent less
// often than Status.
struct CountersMsg {
  Counters explorer;
  LinkCounters link;
  int16_t wheelDrift10UradPerM = 0;  // the drive's drift learnt: heading change per metre, 10 urad/m, + clockwise
  int16_t wheelTurn10Ppm = 0;        // the turns' error learnt: actual / commanded - 1, 10 ppm
};
size_t encodeCounters(const CountersMsg& m, Payload& out);
bool decodeCounters(const uint8_t* p, size_t n, CountersMsg& out);

}  // namespace nxtmap::protocol
