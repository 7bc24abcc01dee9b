#include "host/mapping/MappingRun.hpp"

#include "host/mapping/SimDrive.hpp"


namespace nxtmap::mapping {
namespace {
ExplorerConfig explorerConfigFor(const sim::World& world, const RunConfig& c) {
  ExplorerConfig e;
  e.geometry = sonarGeometryFor(world, c.minRangeM, c.rangeM,
                                c.beamHalfAngleDeg >= 0.0 ? c.beamHalfAngleDeg : c.noise.coneHalfAngleDeg);
  e.searchSliceStates = c.searchSliceStates;
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
      storage_(std::make_unique<Storage>()) {
  map_ = std::make_unique<MapLayers>(storage_->map.view(), Storage::kWidth(), Storage::kHeight());
  planner_ = std::make_unique<TravelPlanner>(storage_->travel.view(), Storage::kWidth(), Storage::kHeight());
  if (config.strategy == Strategy::Propagation) {
    propagation_ = std::make_unique<PropagationExplorer>(*map_, *planner_, explorerConfig_);
    explorer_ = propagation_.get();
  } else {
    frontier_ = std::make_unique<FrontierExplorer>(*map_, *planner_, explorerConfig_);
    explorer_ = frontier_.get();
  }
  PilotConfig pilot;
  pilot.correct = config.poseCorrection;
  pilot_ = std::make_unique<Pilot>(*explorer_, pilot);
  last_ = pilot_->step(DriveEvent::start());
}

MappingRun::~MappingRun() = default;

const PropagationExplorer* MappingRun::propagation() const { return propagation_.get(); }

DriveEvent MappingRun::carryOut(const DriveAction& a) {
  return carryOutOnRobot(robot_, a, explorerConfig_.geometry);
}

bool MappingRun::step() {
  if (pilot_->finished()) return false;
  last_ = pilot_->step(carryOut(last_));
  return !pilot_->finished();
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
