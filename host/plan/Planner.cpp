#include "host/plan/Planner.hpp"

#include "host/plan/AStarPlanner.hpp"
#include "host/plan/DijkstraPlanner.hpp"
#include "host/plan/JumpPointPlanner.hpp"
#include "host/plan/SeedSearch.hpp"

namespace nxtmap::plan {

PlanResult Planner::plan(const mapio::OccupancyMap& map, MapCell from, MapCell to, const PlanOptions& options) {
  const Traversability grid(map, options.unknownTraversable, options.clearanceCells);
  return plan(grid, from, to, options);
}

PlanResult Planner::plan(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) {
  PlanResult r;
  if (!grid.passable(from)) {
    r.status = PlanStatus::StartInvalid;
  } else if (!grid.passable(to)) {
    r.status = PlanStatus::GoalInvalid;
  } else if (from == to) {
    r.status = PlanStatus::Found;
    r.path = {from};
  } else {
    r = search(grid, from, to, options);
  }
  return r;
}

std::unique_ptr<Planner> makePlanner(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::Seed: return std::make_unique<SeedSearch>();
    case Algorithm::AStar: return std::make_unique<AStarPlanner>();
    case Algorithm::Jps: return std::make_unique<JumpPointPlanner>();
    case Algorithm::Dijkstra: return std::make_unique<DijkstraPlanner>();
  }
  return nullptr;
}

const char* algorithmName(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::Seed: return "seed";
    case Algorithm::AStar: return "astar";
    case Algorithm::Jps: return "jps";
    case Algorithm::Dijkstra: return "dijkstra";
  }
  return "?";
}

std::optional<Algorithm> algorithmByName(const std::string& name) {
  for (Algorithm a : {Algorithm::Seed, Algorithm::AStar, Algorithm::Jps, Algorithm::Dijkstra}) {
    if (name == algorithmName(a)) return a;
  }
  return std::nullopt;
}

const char* statusName(PlanStatus status) {
  switch (status) {
    case PlanStatus::Found: return "found";
    case PlanStatus::NoPath: return "no path";
    case PlanStatus::StartInvalid: return "start not passable";
    case PlanStatus::GoalInvalid: return "goal not passable";
    case PlanStatus::NodeLimit: return "node limit reached";
  }
  return "?";
}

}  // namespace nxtmap::plan
