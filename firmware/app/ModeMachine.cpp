#include "firmware/app/ModeMachine.hpp"

#include "firmware/app/MapExport.hpp"

namespace nxtmap::fw {

// Run-end markers for the emulator: g_explorerDone turns 1 when the explorer reports Done, after
// (in the NXTMAP_SIM_GEOMETRY image) the final map was copied to g_mapExport, and g_explorerEnd holds why
// (ExplorerEnd); a house command's end copies the map held then as well.
extern "C" {
volatile uint8_t g_explorerDone = 0;
volatile uint8_t g_explorerEnd = 0;
#if defined(NXTMAP_SIM_GEOMETRY)
MapExport g_mapExport;
#endif
}

// One sensor update: a filtered reading through the pilot into the explorer (marking rules and
// the explorer's next decision), or one more slice of a decision (a Thought event). The emulator
// times this function from entry to return; g_sensorUpdates counts the readings.
extern "C" {
volatile uint32_t g_sensorUpdates = 0;
__attribute__((noinline)) DriveAction nxtmapSensorUpdate(ExplorerStack* stack, const DriveEvent* e) {
  const DriveAction a = stack->step(*e);
  if (e->kind == DriveEvent::Kind::Range) g_sensorUpdates = g_sensorUpdates + 1;
  return a;
}
}

namespace {
// A calibration's sweeps: a quarter turn each way, whatever a run's start does (the published-geometry image
// does not sweep at a run's start).
constexpr int16_t kCalibrationSweepMrad = 1571;
// A fresh brick's unasked calibration (PilotConfig::calibrateUnknownTurns) is the PC's Calibrate.
static_assert(PilotConfig{}.calibrateUnknownTurns == BrickConfig{}.calibrationTurns);

bool isHouseCommand(const protocol::Command& c) {
  return c.kind == protocol::CommandKind::GoTo || c.kind == protocol::CommandKind::EnterRoom ||
         c.kind == protocol::CommandKind::Scan || (c.kind == protocol::CommandKind::Explore && c.explore.confine);
}
}  // namespace

void ModeMachine::carryOut(const protocol::Command& c, uint32_t nowMs) {
  if (isHouseCommand(c)) return houseCommand(c, nowMs);
  leaveHouse();
  switch (c.kind) {
    case protocol::CommandKind::Explore: startExploring(Strategy::Frontier, nowMs); break;
    case protocol::CommandKind::Stop: stop(); break;
    case protocol::CommandKind::FollowPath: followPath(c.path, nowMs); break;
    case protocol::CommandKind::MapChunk: takeMapChunk(c.chunk); break;
    case protocol::CommandKind::SetPose: restAt(c.pose); break;
    case protocol::CommandKind::Calibrate: calibrate(nowMs); break;
    case protocol::CommandKind::GoTo:  // houseCommand
    case protocol::CommandKind::EnterRoom:
    case protocol::CommandKind::Scan: break;
  }
}

void ModeMachine::readButton(Button b, uint32_t nowMs) {
  if (b != candidate_) {
    candidate_ = b;
    candidateSince_ = nowMs;
    return;
  }
  if (nowMs - candidateSince_ < kButtonStableMs || b == lastButton_) return;
  lastButton_ = b;
  if (b != Button::None) leaveHouse();
  switch (b) {
    case Button::Enter: startExploring(Strategy::Propagation, nowMs); break;
    case Button::Right: startExploring(Strategy::Frontier, nowMs); break;
    case Button::Exit: stop(); break;
    case Button::Left: newRoom(); break;
    case Button::None: break;
  }
}

void ModeMachine::drive(uint32_t nowMs) {
  DriveEvent e;
  if (!moving() || !runner_.poll(wheels(), nowMs, e)) return;
  driveMotors();  // the action is over: motors to rest before a possibly long explorer decision
  if (houseActive()) {
    afterHouseStep(house_->step(e), nowMs);
  } else if (mode_ == Mode::Exploring) {
    stepExplorer(e, nowMs);
  } else if (follower_.next(&e, pending_)) {
    runner_.begin(pending_, wheels(), nowMs);
  } else {
    mode_ = Mode::Idle;  // the path's goal reached
    ++finishes_;
  }
}

void ModeMachine::stepExplorer(const DriveEvent& e, uint32_t nowMs) {
  const bool thinking = e.kind == DriveEvent::Kind::Range || e.kind == DriveEvent::Kind::Thought;
  pending_ = thinking ? nxtmapSensorUpdate(&stack_, &e) : stack_.step(e);
  mapChanged();
  if (calibrating_ && (stack_.pilot()->explorerStarted() || pending_.kind == DriveAction::Kind::Done))
    return endCalibration();
  if (pending_.kind == DriveAction::Kind::Done || stack_.finished()) {
    mode_ = Mode::Done;
    ++finishes_;
    keepWheels();
#if defined(NXTMAP_SIM_GEOMETRY)
    g_mapExport.fill(grid());
#endif
    const Explorer* explorer = stack_.explorer();
    g_explorerEnd = static_cast<uint8_t>(explorer != nullptr ? explorer->end() : ExplorerEnd::Running);
    g_explorerDone = 1;
    return;
  }
  runner_.begin(pending_, wheels(), nowMs);
}

void ModeMachine::halt() {
  pc_.stopAll();
  leaveHouse();
  runner_.abort();
  follower_.abort();
  mode_ = Mode::Fault;
}

Pose ModeMachine::pose() const {
  if (houseActive()) return house_->pose();
  if (poseFromPath_) return follower_.pose();
  // (The explorer holds the pose once the pilot has started it: during the start's sweep the robot turns
  // on the spot where it stood.)
  const Explorer* e = stack_.explorer();
  if (e != nullptr && stack_.pilot()->explorerStarted()) return e->pose();
  return restPose_;
}

protocol::BrickReport ModeMachine::report(uint16_t batteryMillivolts) const {
  protocol::BrickReport r;
  r.mode = mode();
  r.pose = pose();
  if (!poseFromPath_) (void)stack_.believedOffset(r.offsetXMm, r.offsetYMm);
  if (hasRun()) r.counters = counters();
  r.batteryMillivolts = batteryMillivolts;
#ifndef NXTMAP_NO_START_SQUARING  // (the RAM-run image learns no wheels)
  const WheelCalibration w = stack_.pilot() != nullptr ? stack_.pilot()->wheels() : learnt_;
  r.wheelDriftUradPerM = w.driftUradPerM;
  r.wheelTurnPpm = w.turnPpm;
#endif
  r.roomId = roomId_;
  r.roomEntry = Cell{0, 0};
  r.path = follower_.progress();
  if (houseActive()) house_->fill(r);
  return r;
}

ActionRunner::Wheels ModeMachine::wheels() const {
  return ActionRunner::Wheels{tacho_.count(config_.leftMotor), tacho_.count(config_.rightMotor)};
}

const WheelCalibration& ModeMachine::knownWheels() {
  if (stack_.pilot() != nullptr) learnt_ = stack_.pilot()->wheels();
  return learnt_;
}

PilotConfig ModeMachine::pilotConfig() {
  PilotConfig p;
  p.wheels = knownWheels();
#ifndef NXTMAP_NO_START_SQUARING
  // A run on an empty map may choose its frame: square to the walls, cells' edges on their faces. On a map
  // the robot already stands in (a PC's, an earlier run's) the frame is given.
  const RoomGrid& g = stack_.map().grid();
  if (g.count(CellState::Free) == 0 && g.count(CellState::Occupied) == 0) p.squareSweepMrad = config_.squareSweepMrad;
#endif
  return p;
}

void ModeMachine::startExploring(Strategy s, uint32_t nowMs) {
  if (mode_ == Mode::Exploring) return;
  safety_.clear();
  tacho_.clearFault();
  follower_.abort();
  if (stack_.running() && !stack_.finished() && !poseFromPath_) {
    // Resume a stopped run: the action that was cut short carries on to where it was going.
    if (!runner_.resume(wheels(), nowMs)) runner_.begin(pending_, wheels(), nowMs);
  } else {
    // A new run on the map as it is (empty in a new room, or what earlier runs, paths and the PC's
    // map left), from where the robot stands.
    const Pose here = pose();
    poseFromPath_ = false;
    restPose_ = here;
    pending_ = stack_.start(s, pilotConfig(), here);
    runner_.begin(pending_, wheels(), nowMs);
  }
  mapChanged();
  mode_ = Mode::Exploring;
}

void ModeMachine::followPath(const protocol::PathMsg& path, uint32_t nowMs) {
  if (mode_ == Mode::Exploring) stop();
  safety_.clear();
  tacho_.clearFault();
  if (!follower_.start(path, pose(), config_.drive.cellMm)) return;  // not from where the robot stands
  poseFromPath_ = true;
  DriveAction first;
  if (follower_.next(nullptr, first)) {
    pending_ = first;
    runner_.begin(first, wheels(), nowMs);
    mode_ = Mode::Following;
  }
}

void ModeMachine::takeMapChunk(const protocol::MapChunkMsg& chunk) {
  // Chunk 0: the robot stays where it is on the PC's map (same frame); the next run starts there.
  if (chunk.chunkIndex == 0) {
    restAt(pose());
    stack_.map().clear();
  } else {
    stop();
  }
  for (uint16_t i = 0; i < chunk.count; ++i) {
    const CellState st = chunk.state(i);
    if (st == CellState::Free)
      (void)stack_.map().markVisited(chunk.cellOf(i));
    else if (st == CellState::Occupied)
      (void)stack_.map().markBlocked(chunk.cellOf(i));
  }
  if (chunk.chunkIndex + 1 >= chunk.chunkCount) link_.mapRestarted();
  mapChanged();
}

void ModeMachine::restAt(const Pose& p) {
  stop();
  restPose_ = p;  // e.g. the robot's cell in a room the PC just uploaded (SetPose), in that room's frame
  stack_.end();   // the next run starts from there on the map as it is
  poseFromPath_ = false;
  mapChanged();
}

void ModeMachine::stop() {
  runner_.abort();
  follower_.abort();
  if (mode_ == Mode::Exploring) keepWheels();
  calibrating_ = false;  // a calibration stopped: a later Explore resumes it, then explores
  if (moving()) mode_ = Mode::Idle;
}

void ModeMachine::keepWheels() {
  if (stack_.pilot() != nullptr) keep(stack_.pilot()->wheels());
}

void ModeMachine::keep(const WheelCalibration& w) {
#ifndef NXTMAP_NO_START_SQUARING  // (the RAM-run image learns no wheels)
  learnt_ = w;
  if (store_ != nullptr) (void)store_->save(learnt_);
#else
  (void)w;
#endif
}

void ModeMachine::calibrate(uint32_t nowMs) {
#ifndef NXTMAP_NO_START_SQUARING  // (the RAM-run image has no sweep: refused like an unknown command)
  if (moving()) stop();
  safety_.clear();
  tacho_.clearFault();
  const Pose here = pose();
  poseFromPath_ = false;
  restPose_ = here;  // where it rests afterwards, square to the walls
  PilotConfig p = pilotConfig();
  p.squareSweepMrad = kCalibrationSweepMrad;
  p.calibrateTurns = config_.calibrationTurns;
  p.approaches = 0;  // where it stands: a calibration never drives off to find a wall
  pending_ = stack_.start(Strategy::Frontier, p, here);
  calibrating_ = true;
  runner_.begin(pending_, wheels(), nowMs);
  mapChanged();
  mode_ = Mode::Exploring;
#else
  (void)nowMs;
#endif
}

void ModeMachine::endCalibration() {
  calibrating_ = false;
  keepWheels();
  stack_.end();  // the explorer never moves: the robot rests where it stood
  mode_ = Mode::Idle;
  ++finishes_;
}

void ModeMachine::newRoom() {
  restAt(Pose{});
  stack_.map().clear();
  link_.mapRestarted();
  ++roomId_;
  mode_ = Mode::Idle;
}

}  // namespace nxtmap::fw
