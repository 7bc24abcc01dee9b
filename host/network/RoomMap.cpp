#include "host/network/RoomMap.hpp"

#include <algorithm>
#include <stdexcept>

namespace nxtmap::network {

RoomMap::RoomMap(int minX, int minY, int width, int height) : minX_(minX), minY_(minY), width_(width), height_(height) {
  if (width < 0 || height < 0) throw std::invalid_argument("RoomMap: negative size");
  cells_.assign(static_cast<size_t>(width) * static_cast<size_t>(height), CellState::Unknown);
}

RoomMap RoomMap::fromGrid(const RoomGrid& grid) {
  const Bounds w = grid.window();
  RoomMap m(w.minX, w.minY, w.width(), w.height());
  for (int16_t y = w.minY; y <= w.maxY && !w.empty(); ++y) {
    for (int16_t x = w.minX; x <= w.maxX; ++x) m.set(Cell{x, y}, grid.at(Cell{x, y}));
  }
  return m;
}

int RoomMap::count(CellState s) const { return static_cast<int>(std::count(cells_.begin(), cells_.end(), s)); }

int RoomMap::firstOccupied(Cell from, Dir d, int maxCells) const {
  for (int k = 1; k <= maxCells; ++k) {
    if (at(advance(from, d, static_cast<int16_t>(k))) == CellState::Occupied) return k;
  }
  return 0;
}

bool RoomMap::operator==(const RoomMap& o) const {
  return minX_ == o.minX_ && minY_ == o.minY_ && width_ == o.width_ && height_ == o.height_ && cells_ == o.cells_;
}

}  // namespace nxtmap::network
