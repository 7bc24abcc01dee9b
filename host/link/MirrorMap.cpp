#include "host/link/MirrorMap.hpp"

#include <algorithm>

#include "common/protocol/Messages.hpp"

namespace nxtmap::link {

bool MirrorMap::applyDelta(const uint8_t* payload, size_t size) {
  protocol::MapDeltaReader r(payload, size);
  if (!r.validate()) return false;
  if (!hasEpoch_ || r.header().epoch != epoch_) {
    cells_.clear();
    hasEpoch_ = true;
    epoch_ = r.header().epoch;
  }
  Cell c;
  CellState s;
  while (r.next(c, s)) {
    if (at(c) != s) ++changes_;
    set(c, s);
  }
  return true;
}

void MirrorMap::clear() {
  cells_.clear();
  hasEpoch_ = false;
}

CellState MirrorMap::at(Cell c) const {
  const auto it = cells_.find(key(c));
  return it == cells_.end() ? CellState::Unknown : it->second;
}

void MirrorMap::set(Cell c, CellState s) {
  if (s == CellState::Unknown)
    cells_.erase(key(c));
  else
    cells_[key(c)] = s;
}

Bounds MirrorMap::bounds() const {
  Bounds b;
  bool first = true;
  for (const auto& [k, s] : cells_) {
    const Cell c = cellOf(k);
    (void)s;
    if (first) {
      b = Bounds{c.x, c.y, c.x, c.y};
      first = false;
    } else {
      b.minX = std::min(b.minX, c.x);
      b.minY = std::min(b.minY, c.y);
      b.maxX = std::max(b.maxX, c.x);
      b.maxY = std::max(b.maxY, c.y);
    }
  }
  return b;
}

void MirrorMap::forEach(const std::function<void(Cell, CellState)>& f) const {
  for (const auto& [k, s] : cells_) {
    f(cellOf(k), s);
  }
}

}  // namespace nxtmap::link
