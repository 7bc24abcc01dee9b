#include "host/plan/ScenarioCheck.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace nxtmap::plan {

std::vector<ProblemOutcome> runProblems(Planner& planner, const Traversability& grid,
                                        const std::vector<ScenarioProblem>& problems, const PlanOptions& options) {
  std::vector<ProblemOutcome> out;
  out.reserve(problems.size());
  for (const ScenarioProblem& p : problems) {
    const auto t0 = std::chrono::steady_clock::now();
    const PlanResult r = planner.plan(grid, p.start, p.goal, options);
    const auto t1 = std::chrono::steady_clock::now();
    ProblemOutcome o;
    o.status = r.status;
    o.length = r.length;
    o.nodes = r.nodesExpanded;
    o.micros = std::chrono::duration<double, std::micro>(t1 - t0).count();
    o.matches = r.found() && std::fabs(r.length - p.optimal) <= kScenarioTolerance;
    out.push_back(o);
  }
  return out;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
  double m = values[mid];
  if (values.size() % 2 == 0) {
    m = (m + *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid))) / 2.0;
  }
  return m;
}

}  // namespace nxtmap::plan
