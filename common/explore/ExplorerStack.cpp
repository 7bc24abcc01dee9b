#include "common/explore/ExplorerStack.hpp"

namespace nxtmap {

ExplorerStack::ExplorerStack(const ExplorerMemory& memory, const ExplorerConfig& config)
    : map_(memory.map, memory.width, memory.height),
      planner_(memory.travel, memory.width, memory.height),
      config_(config) {}

Explorer* ExplorerStack::explorer() {
  if (auto* p = std::get_if<PropagationExplorer>(&explorer_)) return p;
  if (auto* f = std::get_if<FrontierExplorer>(&explorer_)) return f;
  if (auto* g = std::get_if<GoToExplorer>(&explorer_)) return g;
  return nullptr;
}

const Explorer* ExplorerStack::explorer() const { return const_cast<ExplorerStack*>(this)->explorer(); }

bool ExplorerStack::believedOffset(int32_t& xMm, int32_t& yMm) const {
  xMm = yMm = 0;
  if (!pilot_ || !pilot_->explorerStarted()) return false;
  xMm = pilot_->tracker().xMm();
  yMm = pilot_->tracker().yMm();
  return true;
}

DriveAction ExplorerStack::start(Strategy strategy, const PilotConfig& pilot, const Pose& at, Cell target,
                                 const CellSet* shut) {
  end();
  strategy_ = strategy;
  switch (strategy) {
    case Strategy::Propagation: explorer_.emplace<PropagationExplorer>(map_, planner_, config_); break;
    case Strategy::Frontier: explorer_.emplace<FrontierExplorer>(map_, planner_, config_); break;
    case Strategy::GoTo: explorer_.emplace<GoToExplorer>(map_, planner_, config_, target); break;
  }
  pilot_.emplace(*explorer(), pilot);
  pilot_->setVirtualWalls(shut);
  return pilot_->step(DriveEvent::startAt(at));
}

DriveAction ExplorerStack::step(const DriveEvent& e) {
  if (!pilot_) return DriveAction::done();
  return pilot_->step(e);
}

void ExplorerStack::end() {
  pilot_.reset();
  explorer_.emplace<std::monostate>();
}

}  // namespace nxtmap
