#include "common/protocol/Messages.hpp"

#include "common/protocol/FieldIo.hpp"

namespace nxtmap::protocol {
namespace {

// 8-neighbour moves, 0 = N (+y), clockwise.
constexpr int8_t kMoveDx[8] = {0, 1, 1, 1, 0, -1, -1, -1};
constexpr int8_t kMoveDy[8] = {1, 1, 0, -1, -1, -1, 0, 1};

uint8_t moveAt(const PathMsg& m, uint16_t k) { return static_cast<uint8_t>((m.moves[k / 2] >> (4 * (k % 2))) & 0xFu); }
constexpr size_t movesBytes(uint16_t count) { return (count - 1u + 1u) / 2u; }

// Moves 0..7, the unused nibble 0, every cell inside the coordinate range.
bool movesOk(const PathMsg& m) {
  Cell c = m.start;
  for (uint16_t k = 0; k + 1 < m.count; ++k) {
    const uint8_t move = moveAt(m, k);
    if (move > 7) return false;
    c = offset(c, kMoveDx[move], kMoveDy[move]);
    if (!coordOk(c)) return false;
  }
  return (m.count - 1) % 2 == 0 || (m.moves[movesBytes(m.count) - 1] >> 4) == 0;
}

// Cells inside the window, states 0..2, padding 0.
bool chunkOk(const MapChunkMsg& m) {
  if (m.window.empty() || !boundsOk(m.window, 128, 128)) return false;
  if (m.chunkCount == 0 || m.chunkIndex >= m.chunkCount) return false;
  if (static_cast<int>(m.offset) + m.count > m.window.width() * m.window.height()) return false;
  for (size_t i = 0; i < (m.count + 3u) / 4u * 4u; ++i) {
    const uint8_t s = static_cast<uint8_t>((m.states[i / 4] >> (2 * (i % 4))) & 3u);
    if (i < m.count ? s == 3 : s != 0) return false;
  }
  return true;
}

}  // namespace

// Each layout below is the payload of its message, byte for byte in this order (see FieldIo.hpp).
template <>
struct Layout<HelloMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u8(m.version) && io.u32(m.session) && io.flag(m.wantMap);
  }
};
template <>
struct Layout<PathMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.pathId) && io.count(m.count, uint16_t{1}, kMaxPathCells) && io.cell(m.start) &&
           io.bytes(m.moves, movesBytes(m.count)) && io.check([&] { return movesOk(m); });
  }
};
template <>
struct Layout<MapChunkMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.transferId) && io.u16(m.chunkIndex) && io.u16(m.chunkCount) && io.bounds(m.window) &&
           io.u16(m.offset) && io.count(m.count, uint16_t{1}, kChunkCells) && io.bytes(m.states, (m.count + 3u) / 4u) &&
           io.check([&] { return chunkOk(m); });
  }
};
// Five bytes in a loop (the brick's encoder stays small), then the ranges.
template <>
struct Layout<RangeGeometryMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    if (!(io.u8(m.cellCm) && io.u8(m.minCm) && io.u8(m.maxCm) && io.u8(m.mountCm) && io.u8(m.sureCm))) return false;
    return io.check([&] {
      return m.cellCm >= 1 && m.minCm < m.maxCm && m.mountCm <= 50 &&
             (m.sureCm == 0 || (m.sureCm >= m.minCm && m.sureCm <= m.maxCm));
    });
  }
};
template <>
struct Layout<HelloReplyMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u8(m.version) && io.u32(m.session) && io.nibbles(m.gridWidthLog2, m.gridHeightLog2, 1, 7) &&
           io.u16(m.mapEpoch) && io.u16In(m.maxPathCells, 2, 0xFFFF) && io.flag(m.freshSession) && io.part(m.geometry);
  }
};
template <>
struct Layout<Pose> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.cell(m.cell) && io.dir(m.heading);
  }
};
template <>
struct Layout<PoseMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.part(m.pose);
  }
};
template <>
struct Layout<PathProgressMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.pathId) && io.u16In(m.reached, 0, kMaxPathCells - 1) && io.enum8(m.state, PathState::Aborted) &&
           io.cell(m.at);
  }
};
template <>
struct Layout<BatteryMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.millivolts);
  }
};
template <>
struct Layout<StatusMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.enum8(m.mode, BrickMode::Fault) && io.part(m.pose) && io.u16(m.batteryMillivolts) && io.u16(m.mapEpoch) &&
           io.u16(m.roomId) && io.part(m.path) &&
           io.i16In(m.offsetXMm, -StatusMsg::kMaxOffsetMm, StatusMsg::kMaxOffsetMm) &&
           io.i16In(m.offsetYMm, -StatusMsg::kMaxOffsetMm, StatusMsg::kMaxOffsetMm);
  }
};
template <>
struct Layout<CountersMsg> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u32(m.explorer.sensorRequests) && io.u32(m.explorer.rawSamples) && io.u32(m.explorer.cellsMoved) &&
           io.u32(m.explorer.turnEighths) && io.u32(m.explorer.blockedMoves) && io.u32(m.link.telegramsIn) &&
           io.u32(m.link.bytesSkipped) && io.u32(m.link.commandsRun) && io.u32(m.link.duplicates) &&
           io.u32(m.link.retransmits) && io.i16(m.wheelDrift10UradPerM) && io.i16(m.wheelTurn10Ppm);
  }
};

size_t encodeHello(const HelloMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeHello(const uint8_t* p, size_t n, HelloMsg& out) { return decodeFields(p, n, out); }
size_t encodePath(const PathMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodePath(const uint8_t* p, size_t n, PathMsg& out) { return decodeFields(p, n, out); }
size_t encodeMapChunk(const MapChunkMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeMapChunk(const uint8_t* p, size_t n, MapChunkMsg& out) { return decodeFields(p, n, out); }
size_t encodeHelloReply(const HelloReplyMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeHelloReply(const uint8_t* p, size_t n, HelloReplyMsg& out) { return decodeFields(p, n, out); }
size_t encodePose(const PoseMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodePose(const uint8_t* p, size_t n, PoseMsg& out) { return decodeFields(p, n, out); }
size_t encodePathProgress(const PathProgressMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodePathProgress(const uint8_t* p, size_t n, PathProgressMsg& out) { return decodeFields(p, n, out); }
size_t encodeBattery(const BatteryMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeBattery(const uint8_t* p, size_t n, BatteryMsg& out) { return decodeFields(p, n, out); }
size_t encodeStatus(const StatusMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeStatus(const uint8_t* p, size_t n, StatusMsg& out) { return decodeFields(p, n, out); }
size_t encodeCounters(const CountersMsg& m, Payload& out) { return encodeFields(m, out); }
bool decodeCounters(const uint8_t* p, size_t n, CountersMsg& out) { return decodeFields(p, n, out); }

// ---- Path cells ----
Cell PathMsg::cellAt(uint16_t i) const {
  Cell c = start;
  for (uint16_t k = 0; k < i && k + 1 < count; ++k) {
    const uint8_t move = moveAt(*this, k) & 0x7u;
    c = offset(c, kMoveDx[move], kMoveDy[move]);
  }
  return c;
}

bool PathMsg::append(Cell c) {
  if (count == 0) {
    start = c;
    count = 1;
    return coordOk(c);
  }
  if (count >= kMaxPathCells || !coordOk(c)) return false;
  const Cell last = cellAt(static_cast<uint16_t>(count - 1));
  const int ddx = c.x - last.x, ddy = c.y - last.y;
  for (uint8_t move = 0; move < 8; ++move) {
    if (kMoveDx[move] == ddx && kMoveDy[move] == ddy) {
      const uint16_t k = static_cast<uint16_t>(count - 1);
      uint8_t& b = moves[k / 2];
      b = static_cast<uint8_t>((b & ~(0xFu << (4 * (k % 2)))) | (move << (4 * (k % 2))));
      ++count;
      return true;
    }
  }
  return false;
}

// ---- MapChunk cells ----
void MapChunkMsg::setState(uint16_t i, CellState s) {
  uint8_t& b = states[i / 4];
  const int shift = 2 * (i % 4);
  b = static_cast<uint8_t>((b & ~(3u << shift)) | ((static_cast<uint8_t>(s) & 3u) << shift));
}
Cell MapChunkMsg::cellOf(uint16_t i) const {
  const int at = offset + i;
  const int w = window.width();
  return Cell{static_cast<int16_t>(window.minX + at % w), static_cast<int16_t>(window.minY + at / w)};
}

}  // namespace nxtmap::protocol
