#pragma once
#include <cstdint>

#include "common/explore/Explorer.hpp"

namespace nxtmap {

// Frontier exploration (Yamauchi 1997) for a robot whose sensors see along four rays: a
// frontier is an unknown cell a reading from a known-free cell could reveal; the robot goes to
// the reachable spot that sees frontier cells at the lowest travel time (moves and turns),
// reads, and repeats until no frontier is reachable. With gainPerCostUnit > 0 the choice trades
// travel time against the number of unknown cells in view (explore_lite's cost - gain ranking).
class FrontierExplorer final : public Explorer {
 public:
  FrontierExplorer(MapLayers& map, TravelPlanner& planner, const ExplorerConfig& config)
      : Explorer(map, planner, config) {}
  const char* name() const override { return "frontier"; }
  uint16_t goals() const { return goals_; }

 protected:
  Action decide() override;
  bool searchVisit(uint8_t purpose, Cell c, uint16_t cost) override;
  Action searchDone(uint8_t purpose) override;

 private:
  int16_t gainAt(Cell c) const;
  uint16_t goals_ = 0;
  // The search in progress: the best spot so far.
  Cell best_{};
  uint16_t bestCost_ = 0;
  int32_t bestScore_ = 0;
  int16_t bestGain_ = 0;
};

}  // namespace nxtmap
