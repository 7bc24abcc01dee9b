// AStarPlanner: A* with the octile heuristic (admissible and consistent for these moves), a shortest path.
#pragma once

#include "host/plan/Planner.hpp"
#include "host/plan/SearchScratch.hpp"

namespace nxtmap::plan {

class AStarPlanner : public Planner {
 public:
  Algorithm algorithm() const override { return Algorithm::AStar; }

 protected:
  PlanResult search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) override;

 private:
  SearchScratch scratch_;
};

}  // namespace nxtmap::plan
