#pragma once
#include <cstdint>

#include "common/explore/Pose.hpp"
#include "common/explore/Route.hpp"
#include "common/grid/CellSet.hpp"
#include "common/grid/PackedCells.hpp"
#include "common/grid/RoomGrid.hpp"

namespace nxtmap {

// Shortest travel in the robot's time units over known-free cells: a state is a cell and an
// axis (the robot drives forward or backward along its axis without turning); a one-cell move
// costs 1 and a 90 degree turn costs 1. With setTurnNeedsRoom(true) a turn is taken only where
// roomToTurn() holds (a body that sweeps into the neighbouring cells). Breadth-first, so costs come out in order. Memory is
// caller-owned and small enough for the brick: the distance of each state is kept modulo 3
// (2 bits), which is all a path walk-back needs; plus one bit per cell and a ring queue.
class TravelPlanner {
 public:
  struct Storage {
    uint8_t* labels;    // packedBytes(2*w, h, 2): one 2-bit label per (cell, axis)
    uint8_t* reported;  // packedBytes(w, h, 1)
    uint16_t* queue;    // ring of state ids
    uint16_t queueCapacity;
  };
  TravelPlanner(const Storage& storage, int16_t width, int16_t height);

  // Breadth-first from `from`, calling visit(cell, cost) once per reachable cell, cheapest
  // first (the start cell with cost 0). visit returns true to stop the search.
  // Returns false if the queue overflowed (the search is then incomplete).
  template <class Visit>
  bool search(const RoomGrid& grid, Pose from, Visit&& visit);

  // The same search in slices, so one call never costs more than a bounded amount of CPU:
  // start() it, then proceed() with at most maxStates states per call until it is not Running.
  enum class Status : uint8_t { Running, Done };
  void start(Pose from);
  template <class Visit>
  Status proceed(const RoomGrid& grid, Visit&& visit, uint16_t maxStates);
  bool overflowed() const { return overflow_; }

  // Turns only where the body has room (ExplorerConfig::turnNeedsRoom); off by default.
  void setTurnNeedsRoom(bool on) { turnNeedsRoom_ = on; }
#ifndef NXTMAP_NO_START_SQUARING  // the RAM-run image has no room for it
  // Cells where no turn is taken at all (where a turn stalled before); non-owning, nullptr: none.
  void setNoTurn(const CellSet* cells) { noTurn_ = cells; }
  bool turnAllowed(const RoomGrid& grid, Cell c) const {
    return (!turnNeedsRoom_ || roomToTurn(grid, c)) && (noTurn_ == nullptr || !noTurn_->contains(c));
  }
#else
  bool turnAllowed(const RoomGrid& grid, Cell c) const { return !turnNeedsRoom_ || roomToTurn(grid, c); }
#endif
  // Whether a body that sweeps into the neighbouring cells can turn at c: its four neighbours are known free.
  static bool roomToTurn(const RoomGrid& grid, Cell c);

  // After search(): the route to `target`, a cell visited with cost `cost`. Keeps the first
  // Route::kCapacity moves when longer. False when target was not reached.
  bool routeTo(const RoomGrid& grid, Cell target, uint16_t cost, Route& out) const;

 private:
  static constexpr uint8_t kUnseen = 3;
  uint16_t stateId(Cell c, uint8_t axis) const;
  Cell cellOf(const RoomGrid& grid, uint16_t id) const;
  uint8_t label(uint16_t id) const { return labels_.atIndex(id); }
  bool tryPush(uint16_t id, uint8_t lab);
  // routeTo from one of the target's axis states: false unless it walks back to the start.
  bool walkBack(const RoomGrid& grid, uint16_t id, uint16_t cost, Route& out) const;
  void begin();

  PackedCells<2> labels_;
  PackedCells<1> reported_;
  uint16_t* queue_;
  uint16_t capacity_;
  uint16_t head_ = 0, count_ = 0;
  uint16_t startId_ = 0;   // the search's first state
  uint16_t layerEnd_ = 0;  // states left in the current distance layer
  uint16_t dist_ = 0;      // cost of the current layer
  bool overflow_ = false;
  bool turnNeedsRoom_ = false;
#ifndef NXTMAP_NO_START_SQUARING
  const CellSet* noTurn_ = nullptr;
#endif
  int16_t width_, height_;
};

template <class Visit>
bool TravelPlanner::search(const RoomGrid& grid, Pose from, Visit&& visit) {
  start(from);
  while (proceed(grid, visit, 0xFFFF) == Status::Running) {}
  return !overflow_;
}

template <class Visit>
TravelPlanner::Status TravelPlanner::proceed(const RoomGrid& grid, Visit&& visit, uint16_t maxStates) {
  for (uint16_t n = 0; n < maxStates; ++n) {
    if (count_ == 0) return Status::Done;
    if (layerEnd_ == 0) {
      ++dist_;
      layerEnd_ = count_;
    }
    const uint16_t id = queue_[head_];
    head_ = static_cast<uint16_t>((head_ + 1) % capacity_);
    --count_;
    --layerEnd_;
    const Cell c = cellOf(grid, id);
    const uint32_t ci = id >> 1;
    if (reported_.atIndex(ci) == 0) {
      reported_.setIndex(ci, 1);
      if (visit(c, dist_)) {
        count_ = 0;  // stopped: nothing left to do
        return Status::Done;
      }
    }
    const uint8_t axis = id & 1u;
    const uint8_t next = static_cast<uint8_t>((dist_ + 1) % 3);
    if (turnAllowed(grid, c)) tryPush(static_cast<uint16_t>(id ^ 1u), next);  // the other axis
    const Dir a = axis == 0 ? Dir::North : Dir::East;
    const Cell n1 = advance(c, a), n2 = advance(c, opposite(a));
    if (grid.isFree(n1)) tryPush(stateId(n1, axis), next);
    if (grid.isFree(n2)) tryPush(stateId(n2, axis), next);
  }
  return count_ == 0 ? Status::Done : Status::Running;
}

// Storage for a TravelPlanner, sized at compile time.
template <int W, int H, int QUEUE>
struct TravelStorage {
  static_assert(2 * W * H <= 65536, "state ids are 16 bits");
  uint8_t labels[packedBytes(2 * W, H, 2)];
  uint8_t reported[packedBytes(W, H, 1)];
  uint16_t queue[QUEUE];
  TravelPlanner::Storage view() { return TravelPlanner::Storage{labels, reported, queue, QUEUE}; }
};

}  // namespace nxtmap
