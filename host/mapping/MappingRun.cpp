#include "host/mapping/MappingRun.hpp"

#include "host/mapping/SimDrive.hpp"
#include "host/sim/RobotPlacement.hpp"

#include <cmath>

namespace nxtmap::mapping {

// The robot as placed, and the configuration with the truth raster's start cell and the ranges it trusts.
struct MappingRun::Setup {
  sim::RobotPlacement placed;
  RunConfig config;
};

namespace {

ExplorerConfig explorerConfigFor(const sim::World& truth, const RunConfig& c, int mountCm) {
  ExplorerConfig e;
  e.geometry =
      sonarGeometryFor(truth, c.minRangeM, c.rangeM,
                       c.beamHalfAngleDeg >= 0.0 ? c.beamHalfAngleDeg : c.noise.sonar.coneHalfAngleDeg, mountCm);
  e.searchSliceStates = c.searchSliceStates;
  return e;
}

}  // namespace

MappingRun::MappingRun(const sim::Site& site, const RunConfig& config)
    : MappingRun(
          [&] {
            Setup s{sim::placeRobot(
                        site, sim::PlacementRequest{config.robot, config.startPose, config.startCol, config.startRow,
                                                    config.heading, config.startJitterDeg, config.seed, 0.0}),
                    config};
            if (config.robot) {
              s.config.minRangeM = config.robot->minRangeM;
              s.config.rangeM = config.robot->rangeM;
            }
            s.config.startCol = s.placed.grid.startCol;
            s.config.startRow = s.placed.grid.startRow;
            s.config.heading = s.placed.heading;
            return s;
          }(),
          config) {}

MappingRun::MappingRun(const sim::World& world, const RunConfig& config)
    : MappingRun(sim::siteFromRaster(world), config) {}

MappingRun::MappingRun(Setup setup, const RunConfig&)
    : config_(setup.config),
      truth_(std::move(setup.placed.truth)),
      explorerConfig_(explorerConfigFor(truth_, config_, setup.placed.robot.mountCm)),
      frame_(config_.startCol, config_.startRow, config_.heading),
      robot_(setup.placed.scene, setup.placed.robot, setup.placed.grid.frame, setup.placed.start.cm,
             setup.placed.start.headingDeg, config_.noise, config_.seed, config_.sensorReachCm),
      storage_(std::make_unique<Storage>()) {
  map_ = std::make_unique<MapLayers>(storage_->map.view(), Storage::kWidth(), Storage::kHeight());
  planner_ = std::make_unique<TravelPlanner>(storage_->travel.view(), Storage::kWidth(), Storage::kHeight());
  if (config_.strategy == Strategy::Propagation) {
    propagation_ = std::make_unique<PropagationExplorer>(*map_, *planner_, explorerConfig_);
    explorer_ = propagation_.get();
  } else {
    frontier_ = std::make_unique<FrontierExplorer>(*map_, *planner_, explorerConfig_);
    explorer_ = frontier_.get();
  }
  PilotConfig pilot;
  pilot.correct = config_.poseCorrection;
  pilot_ = std::make_unique<Pilot>(*explorer_, pilot);
  last_ = pilot_->step(DriveEvent::start());
}

MappingRun::~MappingRun() = default;

const PropagationExplorer* MappingRun::propagation() const { return propagation_.get(); }

DriveEvent MappingRun::carryOut(const DriveAction& a) {
  return carryOutOnRobot(robot_, a, explorerConfig_.geometry, config_.sensorsTogether);
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

CellState MappingRun::belief(int col, int row) const { return map_->at(frame_.toExplorer(col, row)); }

void MappingRun::believedCell(int& col, int& row) const { frame_.toWorld(explorer_->pose().cell, col, row); }

sim::Heading MappingRun::believedHeading() const { return frame_.toWorld(explorer_->pose().heading); }

}  // namespace nxtmap::mapping
