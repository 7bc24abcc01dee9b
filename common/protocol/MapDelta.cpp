#include "common/protocol/MapDelta.hpp"

#include "common/protocol/FieldIo.hpp"

namespace nxtmap::protocol {

template <>
struct Layout<MapDeltaHeader> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.epoch) && io.nibbles(m.widthLog2, m.heightLog2, 1, 7) && io.bounds(m.window) && io.u8(m.runCount) &&
           io.check([&] {
             return boundsOk(m.window, 1 << m.widthLog2, 1 << m.heightLog2) && (!m.window.empty() || m.runCount == 0);
           });
  }
};

template <>
struct Layout<DeltaRun> {
  template <class Io, class M>
  static bool fields(Io& io, M& m) {
    return io.u16(m.index) && io.count(m.count, uint8_t{1}, kMaxRunCells) && io.bytes(m.packed, (m.count + 3u) / 4u) &&
           io.check([&] { return statesOk(m); });
  }
  // States 0..2 for the run's cells, 0 in the padding.
  static bool statesOk(const DeltaRun& m) {
    for (size_t k = 0; k < (m.count + 3u) / 4u * 4u; ++k) {
      const uint8_t s = static_cast<uint8_t>((m.packed[k / 4] >> (2 * (k % 4))) & 3u);
      if (k < m.count ? s == 3 : s != 0) return false;
    }
    return true;
  }
};

MapDeltaWriter::MapDeltaWriter(Payload& out, const MapDeltaHeader& h, size_t limit)
    : out_(out), limit_(limit < kMinDeltaPayload ? kMinDeltaPayload : (limit > kMaxPayload ? kMaxPayload : limit)) {
  MapDeltaHeader first = h;
  first.runCount = 0;  // counted by addRun
  FieldWriter w(out.bytes, sizeof(out.bytes));
  out.size = w.part(first) ? w.size() : 0;
}

bool MapDeltaWriter::addPackedRun(uint16_t index, uint8_t count, const uint8_t* packed) {
  if (count == 0 || count > kMaxRunCells || !fits(count)) return false;
  DeltaRun run;
  run.index = index;
  run.count = count;
  for (size_t i = 0; i < (count + 3u) / 4u; ++i) run.packed[i] = packed[i];
  FieldWriter w(out_.bytes + out_.size, limit_ - out_.size);
  if (!w.part(run)) return false;
  out_.size += w.size();
  ++runs_;
  out_.bytes[kDeltaHeaderSize - 1] = runs_;
  return true;
}

bool MapDeltaReader::validate() {
  FieldReader r(p_, n_);
  if (!r.part(header_)) return false;
  const int w = 1 << header_.widthLog2, h = 1 << header_.heightLog2;
  for (uint8_t i = 0; i < header_.runCount; ++i) {
    DeltaRun run;
    if (!r.part(run)) return false;
    if (run.index >= w * h || (run.index % w) + run.count > w) return false;  // a run stays in its row
    for (uint8_t k = 0; k < run.count; ++k) {  // and in the window (a narrower one names fewer cells)
      if (!header_.window.contains(cellOfIndex(static_cast<uint16_t>(run.index + k)))) return false;
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
