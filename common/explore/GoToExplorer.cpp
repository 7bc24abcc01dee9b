#include "common/explore/GoToExplorer.hpp"

namespace nxtmap {

Action GoToExplorer::decide() {
  if (pose_.cell == target_ || ++plans_ > kMaxPlans) return Action::done();
  uint16_t cost = 0;
  bool found = false;
  planner_.search(map_.grid(), pose_, [&](Cell c, uint16_t k) {
    if (c != target_) return false;
    cost = k;
    found = true;
    return true;
  });
  if (!found || !travelTo(target_, cost)) return Action::done();
  return follow();
}

}  // namespace nxtmap
