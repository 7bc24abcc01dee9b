// ScenarioCheck: runs Moving AI problems with one planner and checks each against its published optimum.
// Shared by `nxtmap paths` and the benchmark.
#pragma once

#include <string>
#include <vector>

#include "host/plan/MovingAiScenario.hpp"
#include "host/plan/Planner.hpp"

namespace nxtmap::plan {

struct ProblemOutcome {
  PlanStatus status = PlanStatus::NoPath;
  double length = 0.0;  // cells, when found
  uint64_t nodes = 0;
  double micros = 0.0;   // wall time of the search alone
  bool matches = false;  // found with |length - optimal| <= kScenarioTolerance
};

constexpr double kScenarioTolerance = 1e-3;

// Problems whose start or goal is not passable are reported through their status (StartInvalid/GoalInvalid).
std::vector<ProblemOutcome> runProblems(Planner& planner, const Traversability& grid,
                                        const std::vector<ScenarioProblem>& problems, const PlanOptions& options = {});

// Median of the values (0 for none).
double median(std::vector<double> values);

}  // namespace nxtmap::plan
