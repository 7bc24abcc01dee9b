#include "common/explore/FrontierExplorer.hpp"

namespace nxtmap {

int16_t FrontierExplorer::gainAt(Cell c) const {
  int16_t g = 0;
  for (int d = 0; d < 4; ++d) g = static_cast<int16_t>(g + unknownAhead(c, static_cast<Dir>(d)));
  return g;
}

Action FrontierExplorer::decide() {
  best_ = Cell{};
  bestCost_ = 0;
  bestScore_ = 0;
  bestGain_ = 0;
  return startSearch(0);
}

bool FrontierExplorer::searchVisit(uint8_t, Cell c, uint16_t cost) {
  const int32_t w = config_.gainPerCostUnit;
  if (bestGain_ > 0 && w == 0 && cost > bestCost_) return true;  // nearest: done with the layer
  const int16_t g = gainAt(c);
  if (g == 0) return false;
  const int32_t score = w == 0 ? g : static_cast<int32_t>(g) - w * static_cast<int32_t>(cost);
  if (bestGain_ == 0 || score > bestScore_) {
    best_ = c;
    bestCost_ = cost;
    bestScore_ = score;
    bestGain_ = g;
  }
  return false;
}

Action FrontierExplorer::searchDone(uint8_t) {
  if (bestGain_ == 0 || !travelTo(best_, bestCost_)) return Action::done();
  ++goals_;
  return follow();
}

}  // namespace nxtmap
