#include "host/mapping/MappingRun.hpp"

#include <cmath>

namespace nxtmap::mapping {
namespace {
ExplorerConfig explorerConfigFor(const sim::World& world, const RunConfig& c) {
  ExplorerConfig e;
  e.geometry.cellCm = static_cast<int16_t>(std::lround(world.resolutionM() * 100.0));
  e.geometry.minCm = static_cast<int16_t>(std::lround(c.minRangeM * 100.0));
  e.geometry.maxCm = static_cast<int16_t>(std::lround(c.rangeM * 100.0));
  e.geometry.mountCm = 0;
  return e;
}
}  // namespace

MappingRun::MappingRun(const sim::World& world, const RunConfig& config)
    : world_(world),
      config_(config),
      explorerConfig_(explorerConfigFor(world, config)),
      frame_(config.startCol, config.startRow, config.heading),
      robot_(world, config.startCol, config.startRow, config.heading, config.noise, config.seed,
             config.sensorReachCm, 0.0),
      storage_(std::make_unique<Storage>()),
      filter_(explorerConfig_.geometry) {
  map_ = std::make_unique<MapLayers>(storage_->map.view(), Storage::kWidth(), Storage::kHeight());
  planner_ = std::make_unique<TravelPlanner>(storage_->travel.view(), Storage::kWidth(), Storage::kHeight());
  if (config.strategy == Strategy::Propagation) {
    propagation_ = std::make_unique<PropagationExplorer>(*map_, *planner_, explorerConfig_);
    explorer_ = propagation_.get();
  } else {
    frontier_ = std::make_unique<FrontierExplorer>(*map_, *planner_, explorerConfig_);
    explorer_ = frontier_.get();
  }
  last_ = explorer_->step(Event::start());
}

MappingRun::~MappingRun() = default;

const PropagationExplorer* MappingRun::propagation() const { return propagation_.get(); }

Event MappingRun::carryOut(const Action& a) {
  switch (a.kind) {
    case Action::Kind::Read: {
      filter_.reset();
      while (!filter_.done()) {
        filter_.add(static_cast<uint8_t>(robot_.ping(static_cast<int>(a.sensor))));
      }
      return Event::range(a.sensor, filter_.result());
    }
    case Action::Kind::Move: {
      const sim::MoveResult r = robot_.move(a.amount);
      if (r.blocked) return Event::blocked();
      return Event::moved(static_cast<int8_t>(r.cellsMoved));
    }
    case Action::Kind::Turn:
      robot_.turn(a.amount);
      return Event::turned(a.amount);
    case Action::Kind::Done:
      break;
  }
  return Event::start();
}

bool MappingRun::step() {
  if (explorer_->finished()) return false;
  last_ = explorer_->step(carryOut(last_));
  return !explorer_->finished();
}

uint64_t MappingRun::runToEnd() {
  uint64_t n = 0;
  while (step()) ++n;
  return n;
}

CellState MappingRun::belief(int col, int row) const {
  return map_->at(frame_.toExplorer(col, row));
}

void MappingRun::believedCell(int& col, int& row) const { frame_.toWorld(explorer_->pose().cell, col, row); }

sim::Heading MappingRun::believedHeading() const { return frame_.toWorld(explorer_->pose().heading); }

}  // namespace nxtmap::mapping
