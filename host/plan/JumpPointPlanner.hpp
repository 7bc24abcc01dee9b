// JumpPointPlanner: jump point search (Harabor & Grastien 2011) for 8-connected grids without corner
// cutting: A* over jump points only, the same shortest lengths as A* with far fewer heap operations.
// Two ways to find the next jump point: scanning the grid at query time (Algorithm::Jps), or one lookup in a
// JumpTable built once per grid (Algorithm::JpsPlus, JPS+; the table is rebuilt when a new grid is given).
//
// Pruning with no corner cutting: a straight move has a forced neighbour beside the current cell when the
// cell beside the previous one is blocked; a diagonal move has none, but it stops where a straight jump
// along either of its two components finds a jump point. nodesExpanded counts jump points closed.
//
// Both follow "Improving Jump Point Search" (Harabor & Grastien, ICAPS 2014): diagonal jump points are
// pruned as intermediate nodes: a diagonal walk goes on to its end and queues the straight jump points found
// from its cells directly (reached diagonally, then straight), so fewer nodes pass through the open list.
// Jps scans straight lines 64 cells per step in the grid's row and column bitsets (BitGrid).
#pragma once

#include <memory>

#include "host/plan/JumpTable.hpp"
#include "host/plan/Planner.hpp"
#include "host/plan/JumpScratch.hpp"

namespace nxtmap::plan {

class JumpPointPlanner : public Planner {
 public:
  explicit JumpPointPlanner(bool precomputed = false) : precomputed_(precomputed) {}
  Algorithm algorithm() const override { return precomputed_ ? Algorithm::JpsPlus : Algorithm::Jps; }

 protected:
  PlanResult search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) override;

 private:
  bool precomputed_;
  JumpScratch scratch_;
  std::unique_ptr<JumpTable> table_;  // for the last grid (precomputed only)
};

}  // namespace nxtmap::plan
