// SearchScratch: per-planner memory for best-first searches over a Traversability's padded indices,
// reused between queries (a generation stamp instead of clearing), plus the open list.
#pragma once

#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "host/plan/Traversability.hpp"

namespace nxtmap::plan {

class SearchScratch {
 public:
  struct Entry {
    double f;    // g + h
    double g;    // cost so far
    uint32_t i;  // padded index
  };

  // Starts a query on a grid of `size` padded cells.
  void begin(size_t size) {
    if (seen_.size() < size) {
      seen_.assign(size, 0);
      closed_.assign(size, 0);
      g_.assign(size, 0.0);
      parent_.assign(size, 0);
      gen_ = 0;
    }
    if (++gen_ == 0) {  // wrapped: clear the stamps once
      std::fill(seen_.begin(), seen_.end(), 0);
      std::fill(closed_.begin(), closed_.end(), 0);
      gen_ = 1;
    }
    open_ = Heap();
  }

  bool seen(uint32_t i) const { return seen_[i] == gen_; }
  bool closed(uint32_t i) const { return closed_[i] == gen_; }
  void close(uint32_t i) { closed_[i] = gen_; }
  double g(uint32_t i) const { return seen(i) ? g_[i] : std::numeric_limits<double>::infinity(); }
  uint32_t parent(uint32_t i) const { return parent_[i]; }
  // Records a better cost for i and queues it.
  void relax(uint32_t i, double g, double h, uint32_t parent) {
    seen_[i] = gen_;
    g_[i] = g;
    parent_[i] = parent;
    open_.push(Entry{g + h, g, i});
  }
  bool openEmpty() const { return open_.empty(); }
  Entry pop() {
    const Entry e = open_.top();
    open_.pop();
    return e;
  }

 private:
  // Lowest f first; equal f: highest g first (deeper nodes, fewer expansions).
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const { return a.f > b.f || (a.f == b.f && a.g < b.g); }
  };
  using Heap = std::priority_queue<Entry, std::vector<Entry>, Later>;

  std::vector<uint32_t> seen_, closed_;
  std::vector<double> g_;
  std::vector<uint32_t> parent_;
  uint32_t gen_ = 0;
  Heap open_;
};

}  // namespace nxtmap::plan
