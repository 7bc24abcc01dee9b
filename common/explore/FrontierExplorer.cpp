#include "common/explore/FrontierExplorer.hpp"

namespace nxtmap {

int16_t FrontierExplorer::gainAt(Cell c) const {
  int16_t g = 0;
  for (int d = 0; d < 4; ++d) g = static_cast<int16_t>(g + unknownAhead(c, static_cast<Dir>(d)));
  return g;
}

Action FrontierExplorer::decide() {
  const int32_t w = config_.gainPerCostUnit;
  Cell best{};
  uint16_t bestCost = 0;
  int32_t bestScore = 0;
  int16_t bestGain = 0;
  planner_.search(map_.grid(), pose_, [&](Cell c, uint16_t cost) {
    if (bestGain > 0 && w == 0 && cost > bestCost) return true;  // nearest: done with the layer
    const int16_t g = gainAt(c);
    if (g == 0) return false;
    const int32_t score = w == 0 ? g : static_cast<int32_t>(g) - w * static_cast<int32_t>(cost);
    if (bestGain == 0 || score > bestScore) {
      best = c;
      bestCost = cost;
      bestScore = score;
      bestGain = g;
    }
    return false;
  });
  if (bestGain == 0 || !travelTo(best, bestCost)) return Action::done();
  ++goals_;
  return follow();
}

}  // namespace nxtmap
