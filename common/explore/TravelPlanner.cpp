#include "common/explore/TravelPlanner.hpp"

#include "common/check/Check.hpp"

namespace nxtmap {

TravelPlanner::TravelPlanner(const Storage& storage, int16_t width, int16_t height)
    : labels_(storage.labels, static_cast<int16_t>(2 * width), height),
      reported_(storage.reported, width, height),
      queue_(storage.queue),
      capacity_(storage.queueCapacity),
      width_(width),
      height_(height) {
  NXTMAP_CHECK(isPowerOfTwo(width) && isPowerOfTwo(height) && capacity_ > 0);
}

bool TravelPlanner::roomToTurn(const RoomGrid& grid, Cell c) {
  for (int d = 0; d < 4; ++d)
    if (!grid.isFree(advance(c, static_cast<Dir>(d)))) return false;
  return true;
}

void TravelPlanner::begin() {
  labels_.fill(kUnseen);
  reported_.fill(0);
  head_ = count_ = 0;
  overflow_ = false;
}

void TravelPlanner::start(Pose from) {
  begin();
  const uint8_t startAxis = isVertical(from.heading) ? 0 : 1;
  startId_ = stateId(from.cell, startAxis);
  tryPush(startId_, 0);
  layerEnd_ = count_;
  dist_ = 0;
}

uint16_t TravelPlanner::stateId(Cell c, uint8_t axis) const {
  const uint32_t ix = static_cast<uint32_t>(c.x) & static_cast<uint32_t>(width_ - 1);
  const uint32_t iy = static_cast<uint32_t>(c.y) & static_cast<uint32_t>(height_ - 1);
  return static_cast<uint16_t>(((iy * static_cast<uint32_t>(width_) + ix) << 1) | axis);
}

Cell TravelPlanner::cellOf(const RoomGrid& grid, uint16_t id) const {
  const Bounds w = grid.window();
  const int32_t ci = id >> 1;
  const int32_t ix = ci & (width_ - 1), iy = ci / width_;
  const int32_t x = w.minX + ((ix - w.minX) & (width_ - 1));
  const int32_t y = w.minY + ((iy - w.minY) & (height_ - 1));
  return Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)};
}

bool TravelPlanner::tryPush(uint16_t id, uint8_t lab) {
  if (labels_.atIndex(id) != kUnseen) return true;
  if (count_ >= capacity_) {
    overflow_ = true;
    return false;
  }
  labels_.setIndex(id, lab);
  queue_[(head_ + count_) % capacity_] = id;
  ++count_;
  return true;
}

bool TravelPlanner::routeTo(const RoomGrid& grid, Cell target, uint16_t cost, Route& out) const {
  // Where the robot may not turn (turnAllowed) a cell's two axis states are not linked: both may carry the
  // label of `cost` (3 apart), and only one walks back to the start.
  for (uint8_t axis = 0; axis < 2; ++axis) {
    const uint16_t id = stateId(target, axis);
    if (label(id) == cost % 3 && walkBack(grid, id, cost, out)) return true;
  }
  out.clear();
  return false;
}

bool TravelPlanner::walkBack(const RoomGrid& grid, uint16_t id, uint16_t cost, Route& out) const {
  out.clear();
  // Each step back goes to a state one cheaper along an edge the search could take (a move between free
  // cells, a turn where turns are allowed): its neighbours' costs differ by at most 1, so the label, the cost
  // modulo 3, tells the cheaper one. Keeps the last kCapacity moves seen (the route's beginning).
  Dir ring[Route::kCapacity];
  uint16_t moves = 0;
  for (uint16_t d = cost; d > 0; --d) {
    const uint8_t want = static_cast<uint8_t>((d - 1) % 3);
    const Cell c = cellOf(grid, id);
    const uint8_t axis = id & 1u;
    const Dir a = axis == 0 ? Dir::North : Dir::East;
    bool found = false;
    for (int k = 0; k < 2 && !found; ++k) {
      const Dir back = k == 0 ? a : opposite(a);  // predecessor lies in direction `back`
      const Cell p = advance(c, back);
      const uint16_t pid = stateId(p, axis);
      if (grid.isFree(p) && label(pid) == want) {
        ring[moves % Route::kCapacity] = opposite(back);
        ++moves;
        id = pid;
        found = true;
      }
    }
    if (!found) {
      const uint16_t pid = static_cast<uint16_t>(id ^ 1u);
      if (!turnAllowed(grid, c) || label(pid) != want) return false;
      id = pid;
    }
  }
  if (id != startId_) return false;
  const uint16_t kept = moves < Route::kCapacity ? moves : Route::kCapacity;
  for (uint16_t i = 0; i < kept; ++i) {
    out.push(ring[(moves - 1 - i) % Route::kCapacity]);
  }
  return true;
}

}  // namespace nxtmap
