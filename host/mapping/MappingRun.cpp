#include "host/mapping/MappingRun.hpp"

#include "host/mapping/SimDrive.hpp"
#include "host/mapping/SquaredGrid.hpp"
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/TruthRaster.hpp"

#include <cmath>

namespace nxtmap::mapping {

// The robot as placed, and the configuration with the truth raster's start cell and the ranges it trusts.
struct MappingRun::Setup {
  sim::RobotPlacement placed;
  RunConfig config;
};

namespace {

// A free cell of the map beside an unknown one the grid cannot hold: open space cut off by the grid's edge.
bool openAtGridEdge(const RoomGrid& grid) {
  const Bounds w = grid.window();
  for (int16_t y = w.minY; y <= w.maxY; ++y) {
    for (int16_t x = w.minX; x <= w.maxX; ++x) {
      const Cell c{x, y};
      if (!grid.isFree(c)) continue;
      for (const Dir d : {Dir::North, Dir::East, Dir::South, Dir::West}) {
        const Cell n = advance(c, d);
        if (grid.isUnknown(n) && !grid.fits(n)) return true;
      }
    }
  }
  return false;
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
      frame_(config_.startCol, config_.startRow, config_.heading),
      robot_(setup.placed.scene, setup.placed.robot, setup.placed.grid.frame, setup.placed.start.cm,
             setup.placed.start.headingDeg, config_.noise, config_.seed, config_.sensorReachCm),
      buffer_(config_.grid),
      stack_(buffer_.memory(),
             explorerConfigFor(truth_, setup.placed.robot, config_.noise.sonar, config_.minRangeM, config_.rangeM,
                               config_.beamHalfAngleDeg, config_.blindCm, config_.searchSliceStates)) {
  setDownFrameDeg_ = robot_.frame().headingDeg;
  setDownCm_ = sim::Vec2(robot_.xCm(), robot_.yCm());
  startMovedCm_ = setup.placed.startMovedCm;
  PilotConfig pilot;
  pilot.correct = config_.poseCorrection;
  pilot.wheels = config_.storedWheels ? *config_.storedWheels : storedCalibration(config_.noise.wheels);
  pilot.sonarConeMrad = sonarConeMrad(config_.noise.sonar);
  if (config_.calibrateTurns > 0) config_.squareAtStart = true;
  if (config_.squareAtStart) pilot.squareSweepMrad = 1571;
  pilot.calibrateTurns = static_cast<uint8_t>(config_.calibrateTurns);
  if (!config_.calibrateUnknownTurns) pilot.calibrateUnknownTurns = 0;
  last_ = stack_.start(config_.strategy, pilot);
}

MappingRun::~MappingRun() = default;

DriveEvent MappingRun::carryOut(const DriveAction& a) {
  return carryOutOnRobot(robot_, a, stack_.config().geometry, config_.sensorsTogether);
}

bool MappingRun::step() {
  if (stack_.finished()) return false;
  const bool squaring = config_.squareAtStart && !squared_;
  lastEvent_ = carryOut(last_);
  last_ = stack_.step(lastEvent_);
  if (squaring && stack_.pilot() != nullptr && stack_.pilot()->explorerStarted()) layTruthSquare();
  const int64_t known = 2 * static_cast<int64_t>(PilotConfig{}.squaredHeadingMrad);
  if (squareLate_ && !squaring && stack_.pilot()->tracker().thetaVariance() <= known * known) layTruthLate();
  return !stack_.finished();
}

uint64_t MappingRun::runToEnd() {
  uint64_t n = 0;
  while (step()) ++n;
  return n;
}

void MappingRun::layTruthSquare() {
  squared_ = true;
  const SquaredGrid g = squaredGrid(robot_, *stack_.pilot(), explorer().pose().heading, config_.heading, setDownCm_);
  squaredOffDeg_ = g.offDeg;
  if (g.found) squaredTurnedDeg_ = g.turnedDeg;
  squareLate_ = !g.found;
  if (!g.moved) return;  // as laid
  layTruthOn(g.placement, g.placement.startCol, g.placement.startRow, g.heading);
}

void MappingRun::layTruthLate() {
  squareLate_ = false;
  squaredLate_ = true;
  const BelievedGrid g = believedGrid(robot_, *stack_.pilot(), explorer().pose());
  layTruthOn(g.placement, g.originCol, g.originRow, g.heading);
}

void MappingRun::layTruthOn(const sim::Placement& p, int originCol, int originRow, sim::Heading heading) {
  truth_ = sim::rasterizeScene(robot_.scene(), p.frame, p.width, p.height, truth_.name());
  config_.startCol = originCol;
  config_.startRow = originRow;
  config_.heading = heading;
  frame_ = FrameTransform(originCol, originRow, heading);
  robot_.setFrame(p.frame);
}

bool MappingRun::metGridEdge() const {
  return explorer().end() == ExplorerEnd::GridFull || openAtGridEdge(stack_.map().grid());
}

CellState MappingRun::belief(int col, int row) const { return stack_.map().at(frame_.toExplorer(col, row)); }

void MappingRun::believedCell(int& col, int& row) const { frame_.toWorld(explorer().pose().cell, col, row); }

sim::Heading MappingRun::believedHeading() const { return frame_.toWorld(explorer().pose().heading); }

}  // namespace nxtmap::mapping
