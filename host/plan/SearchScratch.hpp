// SearchScratch: per-planner memory for best-first searches over a Traversability's padded indices,
// reused between queries (a generation stamp instead of clearing), plus the open list.
#pragma once

#include <algorithm>
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
    if (nodes_.size() < size) {
      nodes_.assign(size, Node{});
      gen_ = 0;
    }
    if (++gen_ == 0) {  // wrapped: clear the stamps once
      std::fill(nodes_.begin(), nodes_.end(), Node{});
      gen_ = 1;
    }
    open_ = Heap();
  }

  bool seen(uint32_t i) const { return nodes_[i].seen == gen_; }
  bool closed(uint32_t i) const { return nodes_[i].closed == gen_; }
  void close(uint32_t i) { nodes_[i].closed = gen_; }
  double g(uint32_t i) const { return seen(i) ? nodes_[i].g : std::numeric_limits<double>::infinity(); }
  uint32_t parent(uint32_t i) const { return nodes_[i].parent; }
  // Records a better cost for i and queues it.
  void relax(uint32_t i, double g, double h, uint32_t parent) {
    Node& n = nodes_[i];
    n.seen = gen_;
    n.g = g;
    n.parent = parent;
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

  // One record per cell, so a neighbour's state is one memory access.
  struct Node {
    double g = 0.0;       // valid when seen == gen_
    uint32_t parent = 0;  // padded index
    uint32_t seen = 0;    // generation stamps
    uint32_t closed = 0;
  };
  std::vector<Node> nodes_;
  uint32_t gen_ = 0;
  Heap open_;
};

}  // namespace nxtmap::plan
