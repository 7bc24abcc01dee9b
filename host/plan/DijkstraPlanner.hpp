// DijkstraPlanner: plain Dijkstra (no heuristic, fresh memory per query), the reference that the
// differential tests hold astar and jps against. Also the distance field used for `near:LABEL` goals.
#pragma once

#include <vector>

#include "host/plan/Planner.hpp"

namespace nxtmap::plan {

class DijkstraPlanner : public Planner {
 public:
  Algorithm algorithm() const override { return Algorithm::Dijkstra; }

 protected:
  PlanResult search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) override;
};

// Shortest path length from `from` to every cell, indexed by grid.index(); infinity where unreachable.
// Precondition: grid.passable(from).
std::vector<double> distancesFrom(const Traversability& grid, MapCell from);

}  // namespace nxtmap::plan
