#pragma once
#include <cstddef>
#include <cstdint>

#include "common/explore/Counters.hpp"
#include "common/explore/Pose.hpp"
#include "common/grid/Cell.hpp"
#include "common/grid/CellState.hpp"
#include "common/protocol/WireFormat.hpp"

// The payloads of nxtmap packets, each with an encoder and a validating decoder. Encoders write
// explicit little-endian fields and return the payload size (0 = does not fit). Decoders read
// every field, check every range, and return false (leaving `out` unspecified but harmless)
// for anything malformed: truncated, trailing bytes, out-of-range enum or coordinate.
namespace nxtmap::protocol {

struct Payload {
  uint8_t bytes[kMaxPayload] = {};
  size_t size = 0;
};

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

// The robot went through an exit into another room: a new map epoch starts with it.
struct NewRoomMsg {
  uint16_t roomId = 0;  // counts rooms entered since power-on
  Cell entry{};         // entry cell in the new room's frame
};
size_t encodeNewRoom(const NewRoomMsg& m, Payload& out);
bool decodeNewRoom(const uint8_t* p, size_t n, NewRoomMsg& out);

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

// What the brick is doing, small enough to get through a bad link often (21 bytes).
struct StatusMsg {
  BrickMode mode = BrickMode::Idle;
  Pose pose;
  uint16_t batteryMillivolts = 0;
  uint16_t mapEpoch = 0;
  uint16_t roomId = 0;
  PathProgressMsg path;
};
size_t encodeStatus(const StatusMsg& m, Payload& out);
bool decodeStatus(const uint8_t* p, size_t n, StatusMsg& out);

// The explorer's and the link's counters (40 bytes), sent less often than Status.
struct CountersMsg {
  Counters explorer;
  LinkCounters link;
};
size_t encodeCounters(const CountersMsg& m, Payload& out);
bool decodeCounters(const uint8_t* p, size_t n, CountersMsg& out);

// MapDelta: changed cells of the brick's grid, as absolute states (so applying one twice or
// late is harmless). Cells are named by their index on the brick's torus grid (row-major,
// width 2^widthLog2); the window (the bounding box of every known cell, never wider than the
// capacity) turns an index back into coordinates. A run covers `count` consecutive indices of
// one row: [index u16][count u8][states, 2 bits each, ceil(count/4) bytes].
struct MapDeltaHeader {
  uint16_t epoch = 0;     // changes when the brick's map restarts (new room, restructuring, resync)
  uint8_t widthLog2 = 6;  // 1..7 (capacity up to 128)
  uint8_t heightLog2 = 6;
  Bounds window{};
  uint8_t runCount = 0;
};
constexpr size_t kDeltaHeaderSize = 2 + 1 + 8 + 1;
constexpr size_t kRunHeaderSize = 3;
constexpr uint8_t kMaxRunCells = 64;
constexpr size_t kMinDeltaPayload = kDeltaHeaderSize + kRunHeaderSize + 1;  // one run of up to 4 cells
// Bytes one run of `cells` cells takes.
constexpr size_t runBytes(size_t cells) { return kRunHeaderSize + (cells + 3) / 4; }

// Writes a delta payload run by run.
class MapDeltaWriter {
 public:
  // `limit`: the largest payload to build, kMinDeltaPayload..kMaxPayload bytes.
  MapDeltaWriter(Payload& out, const MapDeltaHeader& header, size_t limit = kMaxPayload);
  // Whether a run of `cells` cells still fits.
  bool fits(size_t cells) const { return out_.size + runBytes(cells) <= limit_ && runs_ < 255; }
  // Adds a run; `stateAt(k)` gives the state of cell index+k. False when it does not fit.
  template <class StateAt>
  bool addRun(uint16_t index, uint8_t count, StateAt stateAt) {
    if (count == 0 || count > kMaxRunCells || !fits(count)) return false;
    uint8_t* b = out_.bytes + out_.size;
    b[0] = static_cast<uint8_t>(index);
    b[1] = static_cast<uint8_t>(index >> 8);
    b[2] = count;
    const size_t packed = (count + 3u) / 4u;
    for (size_t i = 0; i < packed; ++i) b[3 + i] = 0;
    for (uint8_t k = 0; k < count; ++k) {
      b[3 + k / 4] = static_cast<uint8_t>(b[3 + k / 4] | ((static_cast<uint8_t>(stateAt(k)) & 3u) << (2 * (k % 4))));
    }
    out_.size += kRunHeaderSize + packed;
    ++runs_;
    out_.bytes[kDeltaHeaderSize - 1] = runs_;
    return true;
  }
  // Adds a run whose states are already packed as the run carries them (see extractCells).
  bool addPackedRun(uint16_t index, uint8_t count, const uint8_t* packed) {
    if (count == 0 || count > kMaxRunCells || !fits(count)) return false;
    uint8_t* b = out_.bytes + out_.size;
    b[0] = static_cast<uint8_t>(index);
    b[1] = static_cast<uint8_t>(index >> 8);
    b[2] = count;
    const size_t n = (count + 3u) / 4u;
    for (size_t i = 0; i < n; ++i) b[3 + i] = packed[i];
    out_.size += kRunHeaderSize + n;
    ++runs_;
    out_.bytes[kDeltaHeaderSize - 1] = runs_;
    return true;
  }
  // The most cells one more run can carry (0 when none fits); fits(n) holds for n <= this.
  size_t cellsThatFit() const {
    if (runs_ == 255 || out_.size + kRunHeaderSize >= limit_) return 0;
    return (limit_ - out_.size - kRunHeaderSize) * 4u;
  }
  uint8_t runs() const { return runs_; }

 private:
  Payload& out_;
  size_t limit_;
  uint8_t runs_ = 0;
};

// Reads a delta: validate() checks all of it first (so a bad delta changes nothing), then
// next() yields each cell with its coordinates and state.
class MapDeltaReader {
 public:
  MapDeltaReader(const uint8_t* p, size_t n) : p_(p), n_(n) {}
  // Parses the header and checks every run. Must return true before next() is used.
  bool validate();
  const MapDeltaHeader& header() const { return header_; }
  bool next(Cell& cell, CellState& state);
  // Coordinates of torus index `index` inside the window.
  Cell cellOfIndex(uint16_t index) const;

 private:
  const uint8_t* p_;
  size_t n_;
  MapDeltaHeader header_;
  bool valid_ = false;
  size_t pos_ = kDeltaHeaderSize;
  uint8_t run_ = 0;
  uint8_t k_ = 0;
};

}  // namespace nxtmap::protocol
