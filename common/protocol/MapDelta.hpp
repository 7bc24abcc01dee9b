#pragma once
#include <cstddef>
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/CellState.hpp"
#include "common/protocol/Payload.hpp"

// MapDelta (brick -> PC): changed cells of the brick's grid, as absolute states (so applying one
// twice or late is harmless). Cells are named by their index on the brick's torus grid
// (row-major, width 2^widthLog2); the window (the bounding box of every known cell, never wider
// than the capacity) turns an index back into coordinates. A run covers `count` consecutive
// indices of one row: [index u16][count u8][states, 2 bits each, ceil(count/4) bytes].
namespace nxtmap::protocol {

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

// One run as it travels: states packed 2 bits each, cell k in bits 2(k%4) of byte k/4, padding 0.
struct DeltaRun {
  uint16_t index = 0;  // torus index of the first cell
  uint8_t count = 0;   // cells, 1..kMaxRunCells, all in the row of `index`
  uint8_t packed[(kMaxRunCells + 3) / 4] = {};
};

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
    if (count == 0 || count > kMaxRunCells) return false;
    uint8_t packed[(kMaxRunCells + 3) / 4] = {};
    for (uint8_t k = 0; k < count; ++k) {
      packed[k / 4] = static_cast<uint8_t>(packed[k / 4] | ((static_cast<uint8_t>(stateAt(k)) & 3u) << (2 * (k % 4))));
    }
    return addPackedRun(index, count, packed);
  }
  // Adds a run whose states are already packed as the run carries them (see extractCells).
  bool addPackedRun(uint16_t index, uint8_t count, const uint8_t* packed);
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
