#include "host/house/HouseMapper.hpp"

#include <cmath>

#include "host/log/Log.hpp"
#include "host/mapping/SimDrive.hpp"
#include "host/mapping/SquaredGrid.hpp"
#include "host/sim/TruthRaster.hpp"

namespace nxtmap::house {
namespace {

sim::RobotPlacement placementFor(const sim::Site& site, const HouseConfig& c) {
  return sim::placeRobot(site, sim::PlacementRequest{c.robot, c.startPose, c.startCol, c.startRow, c.heading,
                                                     c.startJitterDeg, c.seed, 0.0});
}

// The configuration with the start cell on the robot's grid and the ranges the robot trusts.
HouseConfig placedConfig(const sim::RobotPlacement& placed, HouseConfig c) {
  c.startCol = placed.grid.startCol;
  c.startRow = placed.grid.startRow;
  c.heading = placed.heading;
  if (c.robot) {
    c.minRangeM = c.robot->minRangeM;
    c.rangeM = c.robot->rangeM;
  }
  return c;
}

PilotConfig pilotFor(const HouseConfig& c) {
  PilotConfig p;
  p.correct = c.poseCorrection;
  p.wheels = mapping::storedCalibration(c.noise.wheels);
  p.sonarConeMrad = mapping::sonarConeMrad(c.noise.sonar);
  if (c.squareAtStart) p.squareSweepMrad = 1571;  // RoomSession: the first room's run only
  p.calibrateTurns = static_cast<uint8_t>(c.calibrateTurns);  // (with the sweep only: the first room's)
  if (!c.calibrateUnknownTurns) p.calibrateUnknownTurns = 0;
  return p;
}

HousePlannerConfig plannerFor(const HouseConfig& c) {
  HousePlannerConfig p;
  p.doorways = c.doorways;
  p.roomLimits = c.roomLimits;
  p.maxRooms = c.maxRooms;
  p.registerCells = c.registerCells;
  p.maxOpenings = c.maxOpenings;
  p.relocaliseCells = c.relocaliseCells;
  p.poseRangeCm = PilotConfig{}.poseRangeCm;
  p.gridCells = c.grid.cells;
  return p;
}

}  // namespace

HouseMapper::HouseMapper(const sim::World& world, const HouseConfig& config)
    : HouseMapper(sim::siteFromRaster(world), config) {}

HouseMapper::HouseMapper(const sim::Site& site, const HouseConfig& config)
    : HouseMapper(placementFor(site, config), config) {}

HouseMapper::HouseMapper(sim::RobotPlacement placed, const HouseConfig& config)
    : world_(std::move(placed.truth)),
      config_(placedConfig(placed, config)),
      explorerConfig_(mapping::explorerConfigFor(world_, placed.robot, config_.noise.sonar, config_.minRangeM,
                                                 config_.rangeM, -1.0, -1, ExplorerConfig{}.searchSliceStates)),
      frame_(config_.startCol, config_.startRow, config_.heading),
      robot_(placed.scene, placed.robot, placed.grid.frame, placed.start.cm, placed.start.headingDeg, config_.noise,
             config_.seed, config_.sensorReachCm),
      memory_(config_.grid),
      stack_(memory_.memory(), explorerConfig_),
      reachBits_(packedBytes(config_.grid.cells, config_.grid.cells, 1)),
      confinement_(reachBits_.data(), config_.grid.cells, config_.grid.cells, config_.doorways,
                   explorerConfig_.geometry.hitCells()),
      session_(stack_, confinement_, pilotFor(config_)),
      planner_(plannerFor(config_), explorerConfig_.geometry) {
  setDownCm_ = sim::Vec2(robot_.xCm(), robot_.yCm());
}

HouseCounters HouseMapper::counters() const {
  HouseCounters c;
  c.explore = session_.exploreCounters();
  c.travel = session_.travelCounters();
  c.travelBlocked = session_.travelsNotArrived();
  return c;
}

int HouseMapper::run() {
  HouseOrder order = planner_.start();
  while (order.kind != HouseOrder::Kind::Finished) {
    const HouseReport r = carryOut(order);
    order = planner_.on(r);
    logBelief(r.kind == HouseReport::Kind::RoomMapped ? "after room" : "after travel");
  }
  return static_cast<int>(planner_.network().rooms().size());
}

HouseReport HouseMapper::carryOut(const HouseOrder& o) {
  switch (o.kind) {
    case HouseOrder::Kind::ExploreFirstRoom:
      stood_.clear();
      stack_.map().clear();
      drive(session_.exploreRoom(config_.strategy, Pose{}, nullptr));
      break;
    case HouseOrder::Kind::Travel:
      load(o.map);
      drive(session_.goTo(o.target, Pose{}));
      break;
    case HouseOrder::Kind::Cross:
      session_.setPose(o.at);
      stood_.clear();
      drive(session_.cross(o.exit, config_.strategy));
      break;
    case HouseOrder::Kind::Scan: drive(session_.scan()); break;
    case HouseOrder::Kind::Finished: break;
  }
  switch (session_.outcome()) {
    case RoomSession::Outcome::RoomMapped:
      log::debug("house", "room run: end %d, window %dx%d, doorways ignored %d, dropped for capacity %d",
                 static_cast<int>(stack_.explorer()->end()), stack_.map().grid().window().width(),
                 stack_.map().grid().window().height(), confinement_.ignored(), confinement_.overflow());
      return report(HouseReport::Kind::RoomMapped);
    case RoomSession::Outcome::Arrived: return report(HouseReport::Kind::Arrived);
    case RoomSession::Outcome::NotArrived: return report(HouseReport::Kind::NotArrived);
    case RoomSession::Outcome::CrossBlocked: return report(HouseReport::Kind::CrossBlocked);
    case RoomSession::Outcome::Scanned: return report(HouseReport::Kind::Scanned);
    case RoomSession::Outcome::None: break;
  }
  return report(HouseReport::Kind::NotArrived);
}

void HouseMapper::drive(DriveAction a) {
  while (a.kind != DriveAction::Kind::Done) {
    const DriveAction done = a;
    const RoomSession::Phase phase = session_.phase();  // the one the action belongs to
    const DriveEvent answer = mapping::carryOutOnRobot(robot_, a, explorerConfig_.geometry);
    a = session_.step(answer);
    noteWhereItStands();
    if (!squared_ && stack_.pilot() != nullptr && stack_.pilot()->explorerStarted()) {
      layTruthSquare();
    } else if (squareLate_) {
      const int64_t known = 2 * static_cast<int64_t>(PilotConfig{}.squaredHeadingMrad);
      if (!network().rooms().empty() || stack_.pilot() == nullptr)
        squareLate_ = false;  // the first room is over
      else if (stack_.pilot()->tracker().thetaVariance() <= known * known)
        layTruthLate();
    }
    if (trace_ != nullptr) trace_->record(traceRow(phase, done, answer));
  }
}

// While the session maps a room, the cells it believes the robot stands in, each once in a row.
void HouseMapper::noteWhereItStands() {
  if (session_.phase() != RoomSession::Phase::Exploring || stack_.explorer() == nullptr) return;
  const Cell c = session_.pose().cell;
  if (stood_.empty() || !(stood_.back() == c)) stood_.push_back(c);
}

HouseTraceRow HouseMapper::traceRow(RoomSession::Phase phase, const DriveAction& done, const DriveEvent& answer) const {
  static const char* const kOrders[] = {"idle", "room", "travel", "cross", "level", "scan"};
  HouseTraceRow r;
  r.order = kOrders[static_cast<int>(phase)];
  r.done = done;
  r.answer = answer;
  const sim::GridFrame& grid = robot_.frame();
  const sim::Vec2 g = grid.toGrid(sim::Vec2(robot_.xCm(), robot_.yCm()));
  r.trueCol = g.x();
  r.trueRow = g.y();
  r.trueHeadingDeg = std::remainder(robot_.headingDeg() - grid.headingDeg, 360.0);
  if (r.trueHeadingDeg < 0) r.trueHeadingDeg += 360.0;
  const Explorer* explorer = stack_.explorer();
  const Pilot* pilot = stack_.pilot();
  if (explorer == nullptr || pilot == nullptr || !pilot->explorerStarted()) return r;
  r.believed = true;
  // The brick's frame in the house (of the explorer there is now): the travel's, or a room's that started where its
  // crossing ended (the first room's at the house's origin) as the planner will place it.
  network::RoomTransform toHouse = planner_.brickToHouse();
  if (session_.phase() == RoomSession::Phase::Exploring || phase == RoomSession::Phase::Exploring) {
    const Pose c = session_.crossedAt();
    toHouse = network::RoomTransform::fromPose(toHouse.apply(c.cell), toHouse.apply(c.heading));
  }
  const Pose p = explorer->pose();
  frame_.toWorld(toHouse.apply(p.cell), r.believedCol, r.believedRow);
  r.believedHeading = "NESW"[static_cast<int>(frame_.toWorld(toHouse.apply(p.heading)))];
  r.estXMm = pilot->tracker().xMm();
  r.estYMm = pilot->tracker().yMm();
  r.estThetaMrad = pilot->tracker().thetaMrad();
  int col = 0, row = 0;
  grid.cellOf(sim::Vec2(robot_.xCm(), robot_.yCm()), col, row);
  r.lost = col != r.believedCol || row != r.believedRow;
  return r;
}

void HouseMapper::layTruthSquare() {
  squared_ = true;
  const TurnCalibration& t = stack_.pilot()->calibration();
  startCalibration_ = StartCalibration{t.turns(), t.found(), t.found() ? t.errorPpm() : 0, t.turnedBack()};
  if (!config_.squareAtStart) return;
  const mapping::SquaredGrid g =
      mapping::squaredGrid(robot_, *stack_.pilot(), stack_.explorer()->pose().heading, config_.heading, setDownCm_);
  squareLate_ = !g.found;
  if (!g.moved) return;
  layTruthOn(g.placement, g.placement.startCol, g.placement.startRow, g.heading);
}

void HouseMapper::layTruthLate() {
  squareLate_ = false;
  const mapping::BelievedGrid g = mapping::believedGrid(robot_, *stack_.pilot(), stack_.explorer()->pose());
  layTruthOn(g.placement, g.originCol, g.originRow, g.heading);
}

void HouseMapper::layTruthOn(const sim::Placement& p, int originCol, int originRow, sim::Heading heading) {
  world_ = sim::rasterizeScene(robot_.scene(), p.frame, p.width, p.height, world_.name());
  config_.startCol = originCol;
  config_.startRow = originRow;
  config_.heading = heading;
  frame_ = mapping::FrameTransform(originCol, originRow, heading);
  robot_.setFrame(p.frame);
}

void HouseMapper::load(const network::RoomMap& map) {
  stack_.end();
  MapLayers& layers = stack_.map();
  layers.clear();
  for (int y = map.minY(); y <= map.maxY(); ++y) {
    for (int x = map.minX(); x <= map.maxX(); ++x) {
      const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
      const CellState s = map.at(c);
      if (s == CellState::Unknown || !layers.grid().fits(c)) continue;
      (void)(s == CellState::Free ? layers.observeFree(c) : layers.observeOccupied(c));
    }
  }
}

HouseReport HouseMapper::report(HouseReport::Kind kind) const {
  HouseReport r;
  r.kind = kind;
  r.pose = session_.pose();
  if (kind == HouseReport::Kind::RoomMapped) {
    r.map = network::RoomMap::fromGrid(stack_.map().grid());
    for (uint8_t i = 0; i < confinement_.exitCount(); ++i) r.exits.push_back(confinement_.exit(i));
    r.crossedAt = session_.crossedAt();
    r.stood = stood_;
  }
  if (kind == HouseReport::Kind::Scanned) {
    for (int i = 0; i < kSensorCount; ++i) r.scan[i] = session_.scanReading(static_cast<Sensor>(i));
  }
  return r;
}

void HouseMapper::logBelief(const char* when) const {
  if (!log::enabled(log::Level::Debug)) return;
  const Pose b = planner_.belief();
  int col = 0, row = 0;
  frame_.toWorld(b.cell, col, row);
  log::debug("house", "  %s: believed world %d,%d heading %d; true %.1f,%.1f heading %.1f deg", when, col, row,
             static_cast<int>(frame_.toWorld(b.heading)) * 90, robot_.xCm() / 10.0, robot_.yCm() / 10.0,
             robot_.headingDeg());
}

}  // namespace nxtmap::house
