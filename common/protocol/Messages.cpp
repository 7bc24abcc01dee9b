#include "common/protocol/Messages.hpp"

#include "common/protocol/ByteReader.hpp"
#include "common/protocol/ByteWriter.hpp"

namespace nxtmap::protocol {
namespace {

constexpr int16_t kCoordLimit = 16384;  // |coordinate| bound for cells on the wire

bool coordOk(Cell c) { return c.x > -kCoordLimit && c.x < kCoordLimit && c.y > -kCoordLimit && c.y < kCoordLimit; }

void writeCell(ByteWriter& w, Cell c) {
  w.i16(c.x);
  w.i16(c.y);
}
Cell readCell(ByteReader& r) {
  Cell c;
  c.x = r.i16();
  c.y = r.i16();
  return c;
}
void writeBounds(ByteWriter& w, const Bounds& b) {
  w.i16(b.minX);
  w.i16(b.minY);
  w.i16(b.maxX);
  w.i16(b.maxY);
}
Bounds readBounds(ByteReader& r) {
  Bounds b;
  b.minX = r.i16();
  b.minY = r.i16();
  b.maxX = r.i16();
  b.maxY = r.i16();
  return b;
}
bool boundsOk(const Bounds& b, int maxWidth, int maxHeight) {
  if (!coordOk(Cell{b.minX, b.minY}) || !coordOk(Cell{b.maxX, b.maxY})) return false;
  if (b.empty()) return b.minX == 0 && b.minY == 0 && b.maxX == -1 && b.maxY == -1;  // the canonical empty box
  return b.width() <= maxWidth && b.height() <= maxHeight;
}

size_t finish(const ByteWriter& w, Payload& out) {
  out.size = w.ok() ? w.size() : 0;
  return out.size;
}

// 8-neighbour moves, 0 = N (+y), clockwise.
constexpr int8_t kMoveDx[8] = {0, 1, 1, 1, 0, -1, -1, -1};
constexpr int8_t kMoveDy[8] = {1, 1, 0, -1, -1, -1, 0, 1};

void writePathProgress(ByteWriter& w, const PathProgressMsg& m) {
  w.u16(m.pathId);
  w.u16(m.reached);
  w.u8(static_cast<uint8_t>(m.state));
  writeCell(w, m.at);
}
bool readPathProgress(ByteReader& r, PathProgressMsg& m) {
  m.pathId = r.u16();
  m.reached = r.u16();
  const uint8_t state = r.u8();
  m.at = readCell(r);
  m.state = static_cast<PathState>(state);
  return r.ok() && state <= static_cast<uint8_t>(PathState::Aborted) && coordOk(m.at) && m.reached < kMaxPathCells;
}
void writePose(ByteWriter& w, const Pose& p) {
  writeCell(w, p.cell);
  w.u8(static_cast<uint8_t>(p.heading));
}
bool readPose(ByteReader& r, Pose& p) {
  p.cell = readCell(r);
  const uint8_t h = r.u8();
  p.heading = static_cast<Dir>(h & 3u);
  return r.ok() && h <= 3 && coordOk(p.cell);
}

}  // namespace

// ---- Hello ----
size_t encodeHello(const HelloMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u8(m.version);
  w.u32(m.session);
  w.u8(m.wantMap ? 1 : 0);
  return finish(w, out);
}
bool decodeHello(const uint8_t* p, size_t n, HelloMsg& out) {
  ByteReader r(p, n);
  out.version = r.u8();
  out.session = r.u32();
  const uint8_t flags = r.u8();
  out.wantMap = (flags & 1u) != 0;
  return r.ok() && r.atEnd() && flags <= 1;
}

// ---- Path ----
Cell PathMsg::cellAt(uint16_t i) const {
  Cell c = start;
  for (uint16_t k = 0; k < i && k + 1 < count; ++k) {
    const uint8_t move = static_cast<uint8_t>((moves[k / 2] >> (4 * (k % 2))) & 0x7u);
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

size_t encodePath(const PathMsg& m, Payload& out) {
  if (m.count == 0 || m.count > kMaxPathCells) return out.size = 0;
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u16(m.pathId);
  w.u16(m.count);
  writeCell(w, m.start);
  w.bytes(m.moves, (m.count - 1u + 1u) / 2u);
  return finish(w, out);
}
bool decodePath(const uint8_t* p, size_t n, PathMsg& out) {
  ByteReader r(p, n);
  out = PathMsg{};
  out.pathId = r.u16();
  const uint16_t count = r.u16();
  out.start = readCell(r);
  if (!r.ok() || count == 0 || count > kMaxPathCells || !coordOk(out.start)) return false;
  const size_t movesBytes = (count - 1u + 1u) / 2u;
  r.bytes(out.moves, movesBytes);
  if (!r.ok() || !r.atEnd()) return false;
  for (uint16_t k = 0; k + 1 < count; ++k) {
    if (((out.moves[k / 2] >> (4 * (k % 2))) & 0x8u) != 0) return false;  // moves are 0..7
  }
  if ((count - 1) % 2 == 1 && (out.moves[movesBytes - 1] >> 4) != 0) return false;  // unused nibble is 0
  out.count = count;
  // Every cell must stay inside the coordinate range.
  Cell c = out.start;
  for (uint16_t k = 0; k + 1 < count; ++k) {
    const uint8_t move = static_cast<uint8_t>((out.moves[k / 2] >> (4 * (k % 2))) & 0x7u);
    c = offset(c, kMoveDx[move], kMoveDy[move]);
    if (!coordOk(c)) return false;
  }
  return true;
}

// ---- MapChunk ----
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
size_t encodeMapChunk(const MapChunkMsg& m, Payload& out) {
  if (m.count == 0 || m.count > kChunkCells) return out.size = 0;
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u16(m.transferId);
  w.u16(m.chunkIndex);
  w.u16(m.chunkCount);
  writeBounds(w, m.window);
  w.u16(m.offset);
  w.u16(m.count);
  w.bytes(m.states, (m.count + 3u) / 4u);
  return finish(w, out);
}
bool decodeMapChunk(const uint8_t* p, size_t n, MapChunkMsg& out) {
  ByteReader r(p, n);
  out = MapChunkMsg{};
  out.transferId = r.u16();
  out.chunkIndex = r.u16();
  out.chunkCount = r.u16();
  out.window = readBounds(r);
  out.offset = r.u16();
  out.count = r.u16();
  if (!r.ok() || out.count == 0 || out.count > kChunkCells) return false;
  const size_t packed = (out.count + 3u) / 4u;
  r.bytes(out.states, packed);
  if (!r.ok() || !r.atEnd()) return false;
  if (out.window.empty() || !boundsOk(out.window, 128, 128)) return false;
  const int cells = out.window.width() * out.window.height();
  if (out.chunkCount == 0 || out.chunkIndex >= out.chunkCount) return false;
  if (static_cast<int>(out.offset) + out.count > cells) return false;
  for (uint16_t i = 0; i < out.count; ++i) {
    if (out.state(i) != CellState::Unknown && out.state(i) != CellState::Free && out.state(i) != CellState::Occupied)
      return false;
  }
  for (size_t i = out.count; i < packed * 4; ++i) {
    if (((out.states[i / 4] >> (2 * (i % 4))) & 3u) != 0) return false;  // padding is 0
  }
  return true;
}

// ---- HelloReply ----
size_t encodeHelloReply(const HelloReplyMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u8(m.version);
  w.u32(m.session);
  w.u8(static_cast<uint8_t>((m.gridWidthLog2 & 0xFu) | (m.gridHeightLog2 << 4)));
  w.u16(m.mapEpoch);
  w.u16(m.maxPathCells);
  w.u8(m.freshSession ? 1 : 0);
  return finish(w, out);
}
bool decodeHelloReply(const uint8_t* p, size_t n, HelloReplyMsg& out) {
  ByteReader r(p, n);
  out.version = r.u8();
  out.session = r.u32();
  const uint8_t logs = r.u8();
  out.gridWidthLog2 = logs & 0xFu;
  out.gridHeightLog2 = static_cast<uint8_t>(logs >> 4);
  out.mapEpoch = r.u16();
  out.maxPathCells = r.u16();
  const uint8_t fresh = r.u8();
  out.freshSession = fresh == 1;
  return r.ok() && r.atEnd() && fresh <= 1 && out.gridWidthLog2 >= 1 && out.gridWidthLog2 <= 7 &&
         out.gridHeightLog2 >= 1 && out.gridHeightLog2 <= 7 && out.maxPathCells >= 2;
}

// ---- Pose, PathProgress, NewRoom, Battery ----
size_t encodePose(const PoseMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  writePose(w, m.pose);
  return finish(w, out);
}
bool decodePose(const uint8_t* p, size_t n, PoseMsg& out) {
  ByteReader r(p, n);
  return readPose(r, out.pose) && r.atEnd();
}
size_t encodePathProgress(const PathProgressMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  writePathProgress(w, m);
  return finish(w, out);
}
bool decodePathProgress(const uint8_t* p, size_t n, PathProgressMsg& out) {
  ByteReader r(p, n);
  return readPathProgress(r, out) && r.atEnd();
}
size_t encodeNewRoom(const NewRoomMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u16(m.roomId);
  writeCell(w, m.entry);
  return finish(w, out);
}
bool decodeNewRoom(const uint8_t* p, size_t n, NewRoomMsg& out) {
  ByteReader r(p, n);
  out.roomId = r.u16();
  out.entry = readCell(r);
  return r.ok() && r.atEnd() && coordOk(out.entry);
}
size_t encodeBattery(const BatteryMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u16(m.millivolts);
  return finish(w, out);
}
bool decodeBattery(const uint8_t* p, size_t n, BatteryMsg& out) {
  ByteReader r(p, n);
  out.millivolts = r.u16();
  return r.ok() && r.atEnd();
}

// ---- Status, Counters ----
size_t encodeStatus(const StatusMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u8(static_cast<uint8_t>(m.mode));
  writePose(w, m.pose);
  w.u16(m.batteryMillivolts);
  w.u16(m.mapEpoch);
  w.u16(m.roomId);
  writePathProgress(w, m.path);
  return finish(w, out);
}
bool decodeStatus(const uint8_t* p, size_t n, StatusMsg& out) {
  ByteReader r(p, n);
  const uint8_t mode = r.u8();
  out.mode = static_cast<BrickMode>(mode);
  const bool poseOk = readPose(r, out.pose);
  out.batteryMillivolts = r.u16();
  out.mapEpoch = r.u16();
  out.roomId = r.u16();
  const bool pathOk = readPathProgress(r, out.path);
  return r.ok() && r.atEnd() && poseOk && pathOk && mode <= static_cast<uint8_t>(BrickMode::Fault);
}
size_t encodeCounters(const CountersMsg& m, Payload& out) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u32(m.explorer.sensorRequests);
  w.u32(m.explorer.rawSamples);
  w.u32(m.explorer.cellsMoved);
  w.u32(m.explorer.turnEighths);
  w.u32(m.explorer.blockedMoves);
  w.u32(m.link.telegramsIn);
  w.u32(m.link.bytesSkipped);
  w.u32(m.link.commandsRun);
  w.u32(m.link.duplicates);
  w.u32(m.link.retransmits);
  return finish(w, out);
}
bool decodeCounters(const uint8_t* p, size_t n, CountersMsg& out) {
  ByteReader r(p, n);
  out.explorer.sensorRequests = r.u32();
  out.explorer.rawSamples = r.u32();
  out.explorer.cellsMoved = r.u32();
  out.explorer.turnEighths = r.u32();
  out.explorer.blockedMoves = r.u32();
  out.link.telegramsIn = r.u32();
  out.link.bytesSkipped = r.u32();
  out.link.commandsRun = r.u32();
  out.link.duplicates = r.u32();
  out.link.retransmits = r.u32();
  return r.ok() && r.atEnd();
}

// ---- MapDelta ----
MapDeltaWriter::MapDeltaWriter(Payload& out, const MapDeltaHeader& h, size_t limit)
    : out_(out), limit_(limit < kMinDeltaPayload ? kMinDeltaPayload : (limit > kMaxPayload ? kMaxPayload : limit)) {
  ByteWriter w(out.bytes, sizeof(out.bytes));
  w.u16(h.epoch);
  w.u8(static_cast<uint8_t>((h.widthLog2 & 0xFu) | (h.heightLog2 << 4)));
  writeBounds(w, h.window);
  w.u8(0);
  out.size = w.size();
}

bool MapDeltaReader::validate() {
  ByteReader r(p_, n_);
  header_.epoch = r.u16();
  const uint8_t logs = r.u8();
  header_.widthLog2 = logs & 0xFu;
  header_.heightLog2 = static_cast<uint8_t>(logs >> 4);
  header_.window = readBounds(r);
  header_.runCount = r.u8();
  if (!r.ok() || header_.widthLog2 < 1 || header_.widthLog2 > 7 || header_.heightLog2 < 1 || header_.heightLog2 > 7) {
    return false;
  }
  const int w = 1 << header_.widthLog2, h = 1 << header_.heightLog2;
  if (!boundsOk(header_.window, w, h)) return false;
  if (header_.window.empty() && header_.runCount != 0) return false;
  for (uint8_t i = 0; i < header_.runCount; ++i) {
    const uint16_t index = r.u16();
    const uint8_t count = r.u8();
    if (!r.ok() || count == 0 || count > kMaxRunCells) return false;
    if (index >= w * h || (index % w) + count > w) return false;  // a run stays in its row
    uint8_t packed[(kMaxRunCells + 3) / 4];
    const size_t bytes = (count + 3u) / 4u;
    r.bytes(packed, bytes);
    if (!r.ok()) return false;
    for (size_t k = 0; k < bytes * 4; ++k) {
      const uint8_t s = static_cast<uint8_t>((packed[k / 4] >> (2 * (k % 4))) & 3u);
      if (k < count ? s == 3 : s != 0) return false;  // states 0..2, padding 0
    }
  }
  if (!r.atEnd()) return false;
  valid_ = true;
  pos_ = kDeltaHeaderSize;
  run_ = 0;
  k_ = 0;
  return true;
}

Cell MapDeltaReader::cellOfIndex(uint16_t index) const {
  const int w = 1 << header_.widthLog2, h = 1 << header_.heightLog2;
  const int ix = index % w, iy = index / w;
  // The unique x in [minX, minX + w) with x = ix (mod w); the same for y.
  const int x = header_.window.minX + ((ix - header_.window.minX) % w + w) % w;
  const int y = header_.window.minY + ((iy - header_.window.minY) % h + h) % h;
  return Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)};
}

bool MapDeltaReader::next(Cell& cell, CellState& state) {
  if (!valid_) return false;
  while (run_ < header_.runCount) {
    const uint16_t index = static_cast<uint16_t>(p_[pos_] | (p_[pos_ + 1] << 8));
    const uint8_t count = p_[pos_ + 2];
    if (k_ < count) {
      cell = cellOfIndex(static_cast<uint16_t>(index + k_));
      state = static_cast<CellState>((p_[pos_ + kRunHeaderSize + k_ / 4] >> (2 * (k_ % 4))) & 3u);
      ++k_;
      return true;
    }
    pos_ += runBytes(count);
    ++run_;
    k_ = 0;
  }
  return false;
}

}  // namespace nxtmap::protocol
