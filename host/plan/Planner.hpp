// Planner: one interface for every path search on an OccupancyMap.
//
//   auto planner = plan::makePlanner(plan::Algorithm::Jps);
//   plan::PlanResult r = planner->plan(map, {1, 2}, {30, 40}, plan::PlanOptions{});
//   if (r.found()) use(r.path, r.length, r.nodesExpanded);
//
// Moves: 8-connected, straight 1, diagonal sqrt(2), no corner cutting; see Traversability.hpp.
// Algorithms: astar, jps and dijkstra return a shortest path; seed is the published IDA*-like search
// (SeedSearch.hpp), complete but not optimal. A planner keeps scratch memory between queries: use one
// object per thread, and prepare a Traversability once to run many queries on the same map.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "host/mapio/OccupancyMap.hpp"
#include "host/plan/Traversability.hpp"

namespace nxtmap::plan {

struct PlanOptions {
  bool unknownTraversable = false;  // plan through Unknown cells (off: the method's safety rule)
  int clearanceCells = 0;           // keep this many cells from obstacles (and unknown, unless traversable)
  uint64_t maxNodes = 0;            // stop after this many expanded nodes (0: no limit)
  int seedDepthStep = 4;            // seed: the iterative deepening constant c (published: 4)
  int seedTolerance = 3;            // seed: cells of tolerance past the depth limit (published: 3)
};

enum class PlanStatus {
  Found,
  NoPath,        // start and goal are valid but not connected
  StartInvalid,  // outside the map or not passable
  GoalInvalid,   // outside the map or not passable
  NodeLimit,     // maxNodes reached first
};

struct PlanResult {
  PlanStatus status = PlanStatus::NoPath;
  std::vector<MapCell> path;   // start ... goal (inclusive) when found
  double length = 0.0;         // cells (straight 1, diagonal sqrt(2))
  uint64_t nodesExpanded = 0;  // astar/dijkstra: cells closed; jps: jump points closed; seed: nodes visited
  bool found() const { return status == PlanStatus::Found; }
};

enum class Algorithm { Seed, AStar, Jps, Dijkstra };

class Planner {
 public:
  virtual ~Planner() = default;
  virtual Algorithm algorithm() const = 0;

  // Builds the traversability for the options, then plans.
  PlanResult plan(const mapio::OccupancyMap& map, MapCell from, MapCell to, const PlanOptions& options = {});
  // Plans on a prepared grid (options' unknownTraversable and clearanceCells are already in the grid).
  // Start and goal are checked first; start == goal gives a one-cell path of length 0.
  PlanResult plan(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options = {});

 protected:
  // Called with valid, distinct start and goal.
  virtual PlanResult search(const Traversability& grid, MapCell from, MapCell to, const PlanOptions& options) = 0;
};

std::unique_ptr<Planner> makePlanner(Algorithm algorithm);
const char* algorithmName(Algorithm algorithm);  // "seed", "astar", "jps", "dijkstra"
std::optional<Algorithm> algorithmByName(const std::string& name);
const char* statusName(PlanStatus status);

}  // namespace nxtmap::plan
