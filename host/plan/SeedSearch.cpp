#include "host/plan/SeedSearch.hpp"

#include <algorithm>
#include <cstdlib>

namespace nxtmap::plan {

// Rows grow down, so "north" (y up in the thesis) is dr = -1.
const int kSeedDirs[8][2] = {{1, 0}, {1, -1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, 1}, {1, 1}};

namespace {
int sign(int v) { return (v > 0) - (v < 0); }
}  // namespace

void seedChildOrder(int dc, int dr, int out[8]) {
  int first = 0;
  for (int k = 0; k < 8; ++k) {
    if (kSeedDirs[k][0] == sign(dc) && kSeedDirs[k][1] == sign(dr)) first = k;
  }
  // Towards the goal, +45 (counter-clockwise), -45, +90, -90, +135, -135, 180.
  const int turn[8] = {0, 1, -1, 2, -2, 3, -3, 4};
  for (int k = 0; k < 8; ++k) out[k] = (first + turn[k] + 8) % 8;
}

PlanResult SeedSearch::search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) {
  PlanResult r;
  if (visited_.size() < grid.paddedSize()) {
    visited_.assign(grid.paddedSize(), 0);
    gen_ = 0;
  }
  const int step = std::max(1, options.seedDepthStep);
  int limit = std::abs(to.col - from.col) + std::abs(to.row - from.row);
  iterations_ = 0;
  for (;;) {
    ++iterations_;
    const PassEnd five = pass(grid, from, to, limit, 5, options, r);
    if (five == PassEnd::Found || five == PassEnd::NodeLimit) break;
    const PassEnd eight = pass(grid, from, to, limit, 8, options, r);
    if (eight == PassEnd::Found || eight == PassEnd::NodeLimit) break;
    if (eight == PassEnd::Exhausted) {
      r.status = PlanStatus::NoPath;
      break;
    }
    limit += step;
  }
  return r;
}

SeedSearch::PassEnd SeedSearch::pass(const Traversability& grid, MapCell from, MapCell to, int limit, int branch,
                                     const PlanOptions& options, PlanResult& result) {
  if (++gen_ == 0) {
    std::fill(visited_.begin(), visited_.end(), 0);
    gen_ = 1;
  }
  const int tolerance = std::max(0, options.seedTolerance);
  bool cutOff = false;
  auto push = [&](MapCell c, int depth) {
    Frame f;
    f.cell = c;
    f.depth = depth;
    seedChildOrder(to.col - c.col, to.row - c.row, f.order);
    f.count = branch;
    f.next = 0;
    stack_.push_back(f);
    visited_[grid.index(c)] = gen_;
    ++result.nodesExpanded;
  };
  stack_.clear();
  push(from, 0);
  while (!stack_.empty()) {
    Frame& top = stack_.back();
    if (top.next >= top.count) {
      stack_.pop_back();
      continue;
    }
    const int d = top.order[top.next++];
    const int dc = kSeedDirs[d][0];
    const int dr = kSeedDirs[d][1];
    const MapCell child{top.cell.col + dc, top.cell.row + dr};
    if (!grid.canStep(top.cell, dc, dr) || visited_[grid.index(child)] == gen_) continue;
    const int depth = top.depth + 1;
    if (depth > limit) {
      // The cost heuristic with its tolerance: only near the goal, only a few moves more.
      const int away = std::max(std::abs(to.col - child.col), std::abs(to.row - child.row));
      if (depth > limit + tolerance || away > tolerance) {
        cutOff = true;
        continue;
      }
    }
    if (options.maxNodes != 0 && result.nodesExpanded >= options.maxNodes) {
      result.status = PlanStatus::NodeLimit;
      return PassEnd::NodeLimit;
    }
    push(child, depth);
    if (child == to) {
      result.status = PlanStatus::Found;
      result.path.clear();
      result.length = 0.0;
      for (size_t k = 0; k < stack_.size(); ++k) {
        result.path.push_back(stack_[k].cell);
        if (k > 0) {
          const bool diagonal =
              stack_[k].cell.col != stack_[k - 1].cell.col && stack_[k].cell.row != stack_[k - 1].cell.row;
          result.length += diagonal ? kSqrt2 : 1.0;
        }
      }
      return PassEnd::Found;
    }
  }
  return cutOff ? PassEnd::CutOff : PassEnd::Exhausted;
}

}  // namespace nxtmap::plan
