// JumpScratch: the per-planner memory of jump point search, laid out for few cache misses: jump points are
// sparse and far apart, so nearly every successor touches a cold cell. One 16-byte record per cell (g, parent,
// and one word for the generation stamp, the closed flag and the arrival tag: a third less memory than a
// 24-byte record, four records to a cache line). The open list is a binary heap of 16-byte entries that
// keeps its capacity between queries.
//
// A popped entry is current exactly when its cell is not closed yet: with a consistent heuristic a better
// entry for the same cell has a lower f (same h) and is popped, and closes the cell, first.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace nxtmap::plan {

class JumpScratch {
 public:
  struct Entry {
    double f;    // g + h
    float g;     // cost so far, only to break ties (deeper first)
    uint32_t i;  // padded index
  };
  static constexpr uint8_t kMaxTag = 15;

  // Starts a query on a grid of `size` padded cells.
  void begin(std::size_t size) {
    if (cells_.size() < size) {
      cells_.assign(size, Cell{});
      gen_ = 0;
    }
    if (++gen_ > kMaxGen) {  // wrapped: clear the stamps once
      std::fill(cells_.begin(), cells_.end(), Cell{});
      gen_ = 1;
    }
    heap_.clear();
  }

  bool seen(uint32_t i) const { return (cells_[i].state >> kGenShift) == gen_; }
  bool closed(uint32_t i) const { return (cells_[i].state & ~kTagMask) == ((gen_ << kGenShift) | kClosed); }
  void close(uint32_t i) { cells_[i].state |= kClosed; }
  double g(uint32_t i) const { return seen(i) ? cells_[i].g : std::numeric_limits<double>::infinity(); }
  uint32_t parent(uint32_t i) const { return cells_[i].parent; }
  uint8_t tag(uint32_t i) const { return static_cast<uint8_t>(cells_[i].state & kTagMask); }

  // Records a better cost for i (reached from parent, with a tag 0..kMaxTag) and queues it.
  void relax(uint32_t i, double g, double h, uint32_t parent, uint8_t tag) {
    Cell& c = cells_[i];
    c.g = g;
    c.parent = parent;
    c.state = (gen_ << kGenShift) | (tag & kTagMask);
    heap_.push_back(Entry{g + h, static_cast<float>(g), i});
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }
  bool openEmpty() const { return heap_.empty(); }
  Entry pop() {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const Entry e = heap_.back();
    heap_.pop_back();
    return e;
  }

 private:
  static constexpr uint32_t kTagMask = 0x0f;
  static constexpr uint32_t kClosed = 0x10;
  static constexpr int kGenShift = 5;
  static constexpr uint32_t kMaxGen = (1u << (32 - kGenShift)) - 1;

  // Lowest f first; equal f: highest g first (deeper nodes, fewer expansions).
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const { return a.f > b.f || (a.f == b.f && a.g < b.g); }
  };
  static_assert(sizeof(Entry) == 16, "open list entries stay 16 bytes");

  struct Cell {
    double g = 0.0;       // valid when seen
    uint32_t parent = 0;  // padded index, valid when seen
    uint32_t state = 0;   // gen << kGenShift | closed | tag
  };
  static_assert(sizeof(Cell) == 16, "four records to a cache line");
  std::vector<Cell> cells_;
  uint32_t gen_ = 0;
  std::vector<Entry> heap_;
};

}  // namespace nxtmap::plan
