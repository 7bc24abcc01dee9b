// SeedSearch: the published path search (SEED-METHOD.md section 6; thesis sections 3.6 and 4.8), faithfully:
//  - depth-first on the 8-connected grid; a legal move goes to an unvisited passable cell (here with the
//    same no-corner-cutting rule as the other planners); a visited array per search pass, cells stay visited
//    after backtracking (the thesis's "visited nodes" image of the grid);
//  - first heuristic (ordering): children nearest-to-goal first, the published order rotated towards the
//    goal's direction: towards the goal, then 45 degrees either side (counter-clockwise first, with y up as
//    in the thesis), then 90, then 135, then straight away;
//  - second heuristic (cost): depth limit = |a-u| + |b-v| (straight-moves distance from the start); tolerant:
//    past the limit a branch may go on while it is within `seedTolerance` cells (Chebyshev) of the goal, for
//    at most `seedTolerance` extra moves;
//  - limited branch factor: each iteration first searches with only the 5 goal-facing children; if that fails,
//    again with the other 3 added after them (reading: with only the 3 away-facing children no branch could
//    ever get closer to the goal);
//  - iterative deepening: when both passes fail the limit grows by `seedDepthStep` (c = 4 published) until a
//    path is found, or a full pass met no depth cut-off (no legal move remains: no path).
// nodesExpanded = nodes visited, summed over every pass and iteration (what the thesis's table counts).
// The result is a path, not necessarily a shortest one; it always finds one when one exists.
#pragma once

#include <vector>

#include "host/plan/Planner.hpp"

namespace nxtmap::plan {

class SeedSearch : public Planner {
 public:
  Algorithm algorithm() const override { return Algorithm::Seed; }
  // Iterations (depth limits tried) of the last search.
  int lastIterations() const { return iterations_; }

 protected:
  PlanResult search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) override;

 private:
  struct Frame {
    MapCell cell;
    int depth;
    int order[8];  // direction indices, goal-facing first
    int count;     // how many of them to try (5 or 8)
    int next;      // next one to try
  };
  enum class PassEnd { Found, Exhausted, CutOff, NodeLimit };

  PassEnd pass(const Traversability& grid, MapCell from, MapCell to, int limit, int branch, const PlanOptions& options,
               PlanResult& result);

  std::vector<uint32_t> visited_;  // generation stamp per padded index
  uint32_t gen_ = 0;
  std::vector<Frame> stack_;
  int iterations_ = 0;
};

// The eight moves in the published order for a goal at (dc, dr) from the current cell (rows grow down).
// out[k] = direction index into kSeedDirs; the first five face the goal.
void seedChildOrder(int dc, int dr, int out[8]);
extern const int kSeedDirs[8][2];  // (dc, dr), counter-clockwise with y up: E, NE, N, NW, W, SW, S, SE

}  // namespace nxtmap::plan
