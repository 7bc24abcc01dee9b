// MirrorMap: the PC's copy of the brick's room map, kept equal to it by map deltas.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <unordered_map>

#include "common/grid/Cell.hpp"
#include "common/grid/CellState.hpp"

namespace nxtmap::link {

// Known cells (free or occupied) in the explorer's frame of the brick's current room: the
// start cell is (0, 0), +y forward, +x right. Cleared whenever the brick starts a new map epoch.
class MirrorMap {
 public:
  // Applies one MapDelta payload. False (and no change) when it is malformed.
  bool applyDelta(const uint8_t* payload, size_t size);
  void clear();

  CellState at(Cell c) const;
  // Sets a cell (Unknown removes it). For tests and map uploads.
  void set(Cell c, CellState s);

  bool hasEpoch() const { return hasEpoch_; }
  uint16_t epoch() const { return epoch_; }
  // Bounding box of the known cells (empty when none).
  Bounds bounds() const;
  size_t known() const { return cells_.size(); }
  // Calls f(cell, state) for each known cell, in no particular order.
  void forEach(const std::function<void(Cell, CellState)>& f) const;
  // Cells whose state changed through deltas since construction (for throughput figures).
  uint64_t changes() const { return changes_; }

  bool operator==(const MirrorMap& o) const { return cells_ == o.cells_; }

 private:
  static uint32_t key(Cell c) {
    return (static_cast<uint32_t>(static_cast<uint16_t>(c.x)) << 16) | static_cast<uint16_t>(c.y);
  }
  static Cell cellOf(uint32_t k) {
    return Cell{static_cast<int16_t>(static_cast<uint16_t>(k >> 16)), static_cast<int16_t>(static_cast<uint16_t>(k))};
  }
  std::unordered_map<uint32_t, CellState> cells_;
  bool hasEpoch_ = false;
  uint16_t epoch_ = 0;
  uint64_t changes_ = 0;
};

}  // namespace nxtmap::link
