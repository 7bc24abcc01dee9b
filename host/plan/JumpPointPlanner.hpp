// JumpPointPlanner: jump point search (Harabor & Grastien 2011) for 8-connected grids without corner
// cutting: A* over jump points only, the same shortest lengths as A* with far fewer heap operations.
//
// Pruning with no corner cutting: a straight move has a forced neighbour beside the current cell when the
// cell beside the previous one is blocked; a diagonal move has none, but it stops where a straight jump
// along either of its two components finds a jump point. nodesExpanded counts jump points closed.
#pragma once

#include "host/plan/Planner.hpp"
#include "host/plan/SearchScratch.hpp"

namespace nxtmap::plan {

class JumpPointPlanner : public Planner {
 public:
  Algorithm algorithm() const override { return Algorithm::Jps; }

 protected:
  PlanResult search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) override;

 private:
  SearchScratch scratch_;
};

}  // namespace nxtmap::plan
