#include "host/mapping/MappingRun.hpp"

#include "host/mapping/SimDrive.hpp"
#include "host/sim/RobotPlacement.hpp"
#include "host/sim/SceneAxes.hpp"
#include "host/sim/StartJitter.hpp"
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
  startMovedCm_ = setup.placed.startMovedCm;
  PilotConfig pilot;
  pilot.correct = config_.poseCorrection;
  pilot.wheels = storedCalibration(config_.noise.wheels);
  if (config_.calibrateTurns > 0) config_.squareAtStart = true;
  if (config_.squareAtStart) pilot.squareSweepMrad = 1571;
  pilot.calibrateTurns = static_cast<uint8_t>(config_.calibrateTurns);
  last_ = stack_.start(config_.strategy, pilot);
}

MappingRun::~MappingRun() = default;

DriveEvent MappingRun::carryOut(const DriveAction& a) {
  return carryOutOnRobot(robot_, a, stack_.config().geometry, config_.sensorsTogether);
}

bool MappingRun::step() {
  if (stack_.finished()) return false;
  const bool squaring = config_.squareAtStart && !squared_;
  last_ = stack_.step(carryOut(last_));
  if (squaring && stack_.pilot() != nullptr && stack_.pilot()->explorerStarted()) layTruthSquare();
  return !stack_.finished();
}

uint64_t MappingRun::runToEnd() {
  uint64_t n = 0;
  while (step()) ++n;
  return n;
}

void MappingRun::layTruthSquare() {
  squared_ = true;
  // The walls' axis nearest to where the robot now faces: the frame it believes it maps in; with no straight
  // wall seen, the frame it was set down in (turned back to where it was set down).
  const double heading = robot_.headingDeg();
  const double off = std::remainder(heading - sim::sceneAxesDeg(robot_.scene()), 90.0);
  const bool found = stack_.pilot()->squaring().result().found;
  const double axis = found ? heading - off : robot_.frame().headingDeg + 90.0 * static_cast<int>(config_.heading);
  if (found) squaredOffDeg_ = std::fabs(off);
  const sim::Heading quarter = static_cast<sim::Heading>(sim::squareQuarter(axis));
  const double turn = sim::squareRemainderDeg(axis);
  // The cell's centre where the pilot believes it: off the robot by the offset the nearest walls gave it.
  const PoseTracker& tracker = stack_.pilot()->tracker();
  const Dir h = explorer().pose().heading;
  const double forwardCm = tracker.along(h) / 10.0, rightCm = tracker.along(rotate(h, 1)) / 10.0;
  const double rad = axis * 3.14159265358979323846 / 180.0;
  const sim::Vec2 forward(std::sin(rad), -std::cos(rad)), right(std::cos(rad), std::sin(rad));
  const sim::Vec2 centre = sim::Vec2(robot_.xCm(), robot_.yCm()) - forwardCm * forward - rightCm * right;
  if (quarter == config_.heading && std::fabs(turn - robot_.frame().headingDeg) < 1e-6 && forwardCm == 0.0 &&
      rightCm == 0.0)
    return;  // as laid
  const sim::Placement p = sim::placeOnGrid(robot_.scene(), centre, turn, robot_.frame().cellCm);
  truth_ = sim::rasterizeScene(robot_.scene(), p.frame, p.width, p.height, truth_.name());
  config_.startCol = p.startCol;
  config_.startRow = p.startRow;
  config_.heading = quarter;
  frame_ = FrameTransform(p.startCol, p.startRow, quarter);
  robot_.setFrame(p.frame);
}

bool MappingRun::metGridEdge() const {
  return explorer().end() == ExplorerEnd::GridFull || openAtGridEdge(stack_.map().grid());
}

CellState MappingRun::belief(int col, int row) const { return stack_.map().at(frame_.toExplorer(col, row)); }

void MappingRun::believedCell(int& col, int& row) const { frame_.toWorld(explorer().pose().cell, col, row); }

sim::Heading MappingRun::believedHeading() const { return frame_.toWorld(explorer().pose().heading); }

}  // namespace nxtmap::mapping
