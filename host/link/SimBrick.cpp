#include "host/link/SimBrick.hpp"

#include "host/mapping/SimDrive.hpp"

#include <cmath>

namespace nxtmap::link {

using namespace protocol;

namespace {

// The link as configured, telling the PC the explorer's geometry (HelloReply).
BrickLinkConfig linkConfigFor(BrickLinkConfig link, const RangeGeometry& geometry) {
  link.geometry = rangeGeometryMsgOf(geometry);
  return link;
}

// World heading (N, E, S, W) as a sim::Heading step.
sim::Heading headingOf(int quarters) { return static_cast<sim::Heading>(((quarters % 4) + 4) % 4); }

// The frame in which `brickCell` (facing `brickHeading`) is world cell (col, row) facing `worldHeading`.
mapping::FrameTransform frameThrough(Cell brickCell, Dir brickHeading, int col, int row, sim::Heading worldHeading) {
  const sim::Heading h0 = headingOf(static_cast<int>(worldHeading) - static_cast<int>(brickHeading));
  // Origin = world cell minus the rotated brick cell: measure the rotation with a frame at 0,0.
  const mapping::FrameTransform atZero(0, 0, h0);
  int dc = 0, dr = 0;
  atZero.toWorld(brickCell, dc, dr);
  return mapping::FrameTransform(col - dc, row - dr, h0);
}

// The robot as the run configuration places it in the site.
sim::RobotPlacement placementFor(const sim::Site& site, const mapping::RunConfig& c) {
  return sim::placeRobot(site, sim::PlacementRequest{c.robot, c.startPose, c.startCol, c.startRow, c.heading,
                                                     c.startJitterDeg, c.seed, 0.0});
}

// The run configuration with the start cell on the robot's grid and the ranges the robot trusts.
SimBrickConfig placedConfig(const sim::RobotPlacement& placed, SimBrickConfig c) {
  c.run.startCol = placed.grid.startCol;
  c.run.startRow = placed.grid.startRow;
  c.run.heading = placed.heading;
  if (c.run.robot) {
    c.run.minRangeM = c.run.robot->minRangeM;
    c.run.rangeM = c.run.robot->rangeM;
  }
  return c;
}

}  // namespace

SimBrick::SimBrick(const sim::World& world, const SimBrickConfig& config)
    : SimBrick(sim::siteFromRaster(world), config) {}

SimBrick::SimBrick(const sim::Site& site, const SimBrickConfig& config)
    : SimBrick(placementFor(site, config.run), config) {}

SimBrick::SimBrick(sim::RobotPlacement placed, const SimBrickConfig& config)
    : world_(std::move(placed.truth)),
      config_(placedConfig(placed, config)),
      frame_(config_.run.startCol, config_.run.startRow, config_.run.heading),
      robot_(placed.scene, placed.robot, placed.grid.frame, placed.start.cm, placed.start.headingDeg, config_.run.noise,
             config_.run.seed, config_.run.sensorReachCm),
      buffer_(config_.run.grid),
      stack_(buffer_.memory(),
             mapping::explorerConfigFor(world_, placed.robot, config_.run.noise.sonar, config_.run.minRangeM,
                                        config_.run.rangeM, config_.run.beamHalfAngleDeg, -1,
                                        config_.run.searchSliceStates)),
      reach_(packedBytes(config_.run.grid.cells, config_.run.grid.cells, 1)),
      confinement_(reach_.data(), config_.run.grid.cells, config_.run.grid.cells, DoorwayLimits{4, 15, 3, 2},
                   stack_.config().geometry.hitCells()),
      house_(stack_, confinement_, pilotConfig()),
      shadow_(packedBytes(stack_.map().grid().capacityWidth(), stack_.map().grid().capacityHeight(), 2)),
      link_(stack_.map().grid(), shadow_.data(), linkConfigFor(config.link, stack_.config().geometry)) {}

SimBrick::~SimBrick() = default;

void SimBrick::receive(const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) link_.receive(data[i]);
}

Pose SimBrick::pose() const {
  if (house_.active()) return house_.pose();
  return stack_.explorer() != nullptr ? stack_.explorer()->pose() : restPose_;
}

Counters SimBrick::counters() const { return stack_.counters(); }

bool SimBrick::finished() const { return stack_.finished(); }

void SimBrick::trueCell(int& col, int& row) const {
  col = robot_.col();
  row = robot_.row();
}

PilotConfig SimBrick::pilotConfig() const {
  PilotConfig p;
  p.correct = config_.run.poseCorrection;
  p.wheels = learnt_ ? *learnt_ : mapping::storedCalibration(config_.run.noise.wheels);
  return p;
}

WheelCalibration SimBrick::wheels() const {
  if (stack_.pilot() != nullptr) return stack_.pilot()->wheels();
  return house_.active() ? house_.wheels() : pilotConfig().wheels;
}

BrickReport SimBrick::report() const {
  BrickReport r;
  r.mode = mode_;
  r.pose = pose();
  (void)stack_.believedOffset(r.offsetXMm, r.offsetYMm);
  r.counters = counters();
  r.batteryMillivolts = config_.batteryMillivolts;
  const WheelCalibration w = wheels();
  r.wheelDriftUradPerM = w.driftUradPerM;
  r.wheelTurnPpm = w.turnPpm;
  r.roomId = roomId_;
  r.path = path_;
  if (house_.active()) house_.fill(r);
  return r;
}

std::vector<uint8_t> SimBrick::transmit(uint32_t nowMs, size_t maxBytes) {
  const BrickReport r = report();
  Frame f;
  while (txQueue_.size() < maxBytes && link_.transmit(nowMs, r, f))
    txQueue_.insert(txQueue_.end(), f.bytes, f.bytes + f.size);
  const size_t n = std::min(maxBytes, txQueue_.size());
  std::vector<uint8_t> out(txQueue_.begin(), txQueue_.begin() + static_cast<long>(n));
  txQueue_.erase(txQueue_.begin(), txQueue_.begin() + static_cast<long>(n));
  return out;
}

void SimBrick::linkLost() {
  link_.linkLost();
  txQueue_.clear();
}

void SimBrick::stopMoving() {
  calibrating_ = false;
  if (mode_ == BrickMode::Following && path_.state == PathState::Following) path_.state = PathState::Aborted;
  if (mode_ == BrickMode::Exploring || mode_ == BrickMode::Following) mode_ = BrickMode::Idle;
}

// A run holds the pose while it lives; everything that moves the robot otherwise ends it here.
void SimBrick::setPose(const Pose& p) {
  stopMoving();
  // The cell the brick believed it stood on is now called p: the frame follows.
  int col = 0, row = 0;
  const Pose before = pose();
  frame_.toWorld(before.cell, col, row);
  frame_ = frameThrough(p.cell, p.heading, col, row, frame_.toWorld(before.heading));
  restPose_ = p;
  stack_.end();
}

void SimBrick::startExploring() {
  if (stack_.running() && !stack_.finished()) {
    mode_ = BrickMode::Exploring;  // resume: the cut-short action carries on
    return;
  }
  // A new run on the map as it is, from where the robot stands.
  restPose_ = pose();
  pending_ = stack_.start(config_.run.strategy, pilotConfig(), restPose_);
  mode_ = stack_.finished() ? BrickMode::Done : BrickMode::Exploring;
}

void SimBrick::calibrate() {
  stopMoving();
  restPose_ = pose();
  PilotConfig p = pilotConfig();
  p.squareSweepMrad = 1571;  // a quarter turn each way, as the brick's calibration
  p.calibrateTurns = 4;
  p.approaches = 0;  // where it stands
  pending_ = stack_.start(config_.run.strategy, p, restPose_);
  calibrating_ = true;
  mode_ = BrickMode::Exploring;
}

void SimBrick::endCalibration() {
  calibrating_ = false;
  learnt_ = stack_.pilot()->wheels();
  stack_.end();
  mode_ = BrickMode::Idle;
}

void SimBrick::takeMapChunk(const MapChunkMsg& chunk) {
  ++mapChunks_;
  stopMoving();
  if (chunk.chunkIndex == 0) {
    restPose_ = pose();  // the robot stays where it is on the PC's map (same frame)
    stack_.end();
    stack_.map().clear();
  }
  for (uint16_t i = 0; i < chunk.count; ++i) {
    const CellState st = chunk.state(i);
    if (st == CellState::Free)
      (void)stack_.map().markVisited(chunk.cellOf(i));
    else if (st == CellState::Occupied)
      (void)stack_.map().markBlocked(chunk.cellOf(i));
  }
  if (chunk.chunkIndex + 1 >= chunk.chunkCount) link_.mapRestarted();
}

void SimBrick::newRoom() {
  stopMoving();
  int col = 0, row = 0;
  const Pose before = pose();
  frame_.toWorld(before.cell, col, row);
  frame_ = mapping::FrameTransform(col, row, frame_.toWorld(before.heading));
  restPose_ = Pose{};
  stack_.end();
  stack_.map().clear();
  link_.mapRestarted();
  ++roomId_;
  mode_ = BrickMode::Idle;
}

void SimBrick::newRoomFrame(const Pose& origin) {
  int col = 0, row = 0;
  frame_.toWorld(origin.cell, col, row);
  frame_ = mapping::FrameTransform(col, row, frame_.toWorld(origin.heading));
}

void SimBrick::houseCommand(const Command& c) {
  if (mode_ == BrickMode::Following && path_.state == PathState::Following) path_.state = PathState::Aborted;
  const Pose here = pose();
  if (!house_.active()) house_.useWheels(wheels());  // a house starts from what the brick knows
  if (c.kind == CommandKind::Explore) {
    newRoomFrame(here);
    pending_ = house_.explore(c.explore, here, roomId_);
  } else if (c.kind == CommandKind::GoTo) {
    pending_ = house_.goTo(c.goTo, here);
  } else if (c.kind == CommandKind::Scan) {
    pending_ = house_.scan(c.scan, here);
  } else {
    pending_ = house_.enterRoom(c.enterRoom, here);
  }
  if (house_.takeMapRestart()) link_.mapRestarted();
  roomId_ = house_.roomId();
  mode_ = house_.mode();
}

void SimBrick::carryOut(const Command& c) {
  executed_.push_back(c.seq);
  const bool houseCommand = c.kind == CommandKind::GoTo || c.kind == CommandKind::EnterRoom ||
                            c.kind == CommandKind::Scan || (c.kind == CommandKind::Explore && c.explore.confine);
  if (houseCommand) return this->houseCommand(c);
  if (house_.active()) {  // any other command ends the house command and its reports
    house_.abort();
    learnt_ = house_.wheels();  // what the house's runs learnt: where the brick's next runs start
    house_.deactivate();
    restPose_ = house_.pose();
    stack_.end();
  }
  switch (c.kind) {
    case CommandKind::Explore: startExploring(); break;
    case CommandKind::Stop: stopMoving(); break;
    case CommandKind::FollowPath: {
      if (mode_ == BrickMode::Exploring) stopMoving();
      pathMsg_ = c.path;
      path_ = PathProgressMsg{c.path.pathId, 0, PathState::Following, c.path.start};
      const Pose here = pose();
      if (c.path.start != here.cell) {
        path_.state = PathState::Aborted;  // the path must start where the robot stands
        mode_ = BrickMode::Idle;
        break;
      }
      // The path moves the robot: the run (if any) no longer knows where it is.
      restPose_ = here;
      stack_.end();
      mode_ = BrickMode::Following;
      if (c.path.count == 1) {
        path_.state = PathState::Reached;
        mode_ = BrickMode::Idle;
      }
      break;
    }
    case CommandKind::MapChunk: takeMapChunk(c.chunk); break;
    case CommandKind::SetPose: setPose(c.pose); break;
    case CommandKind::Calibrate: calibrate(); break;
    case CommandKind::GoTo:
    case CommandKind::EnterRoom:
    case CommandKind::Scan: break;  // houseCommand
  }
}

}  // namespace nxtmap::link
