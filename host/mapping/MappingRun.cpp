#include "host/mapping/MappingRun.hpp"

#include <algorithm>
#include <cmath>

namespace nxtmap::mapping {
namespace {
ExplorerConfig explorerConfigFor(const sim::World& world, const RunConfig& c) {
  ExplorerConfig e;
  e.geometry.cellCm = static_cast<int16_t>(std::lround(world.resolutionM() * 100.0));
  e.geometry.minCm = static_cast<int16_t>(std::lround(c.minRangeM * 100.0));
  e.geometry.maxCm = static_cast<int16_t>(std::lround(c.rangeM * 100.0));
  e.geometry.mountCm = 0;
  e.searchSliceStates = c.searchSliceStates;
  const double beam = c.beamHalfAngleDeg >= 0.0 ? c.beamHalfAngleDeg : c.noise.coneHalfAngleDeg;
  if (beam > 0.0) {
    const double sure = 0.5 * e.geometry.cellCm / std::tan(beam * 3.141592653589793 / 180.0) - e.geometry.mountCm;
    if (sure < e.geometry.maxCm) e.geometry.sureCm = static_cast<int16_t>(std::max(e.geometry.minCm + 1.0, std::floor(sure)));
  }
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
  switch (a.kind) {
    case DriveAction::Kind::Read: {
      RangeFilter filter(explorerConfig_.geometry);
      while (!filter.done()) {
        filter.add(static_cast<uint8_t>(robot_.ping(static_cast<int>(a.sensor))));
      }
      return DriveEvent::range(a.sensor, filter.result());
    }
    case DriveAction::Kind::Rotate:
      robot_.rotate(a.value * (180.0 / 3141.592653589793));
      return DriveEvent::rotated();
    case DriveAction::Kind::Drive:
      return DriveEvent::driven(!robot_.drive(a.value / 10.0));
    case DriveAction::Kind::Think:
      return DriveEvent::thought();
    case DriveAction::Kind::Done:
      break;
  }
  return DriveEvent::start();
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
