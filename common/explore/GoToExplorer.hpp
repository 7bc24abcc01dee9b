// GoToExplorer: an explorer whose only goal is to reach one cell over a map it is given (the rooms
// already mapped), so the pilot can carry the robot there with its pose corrections against the
// known walls, like any exploration move. It still reads whatever unknown lies ahead (the base
// class's rule) and replans when a move is blocked; it gives up after kMaxPlans plans.
#pragma once

#include "common/explore/Explorer.hpp"

namespace nxtmap {

class GoToExplorer final : public Explorer {
 public:
  static constexpr int kMaxPlans = 50;
  GoToExplorer(MapLayers& map, TravelPlanner& planner, const ExplorerConfig& config, Cell target)
      : Explorer(map, planner, config), target_(target) {}
  const char* name() const override { return "goto"; }
  bool arrived() const { return pose().cell == target_; }

 protected:
  Action decide() override;

 private:
  Cell target_;
  int plans_ = 0;
};

}  // namespace nxtmap
