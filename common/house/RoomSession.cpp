#include "common/house/RoomSession.hpp"

#include "common/house/RoomFrame.hpp"

namespace nxtmap {
namespace {
constexpr int32_t kQuarterMrad = 1571;  // 90 degrees, rounded (0.2 mrad short of pi/2)
}  // namespace

RoomSession::RoomSession(ExplorerStack& stack, RoomConfinement& confinement, const PilotConfig& pilot)
    : stack_(stack), confinement_(confinement), pilot_(pilot) {}

PilotConfig RoomSession::pilotConfig() const {
  PilotConfig p = pilot_;
  p.startHeadingVarianceMrad2 = pilot_.correct ? headingVariance_ : 0;
  // The sweep square to the walls: the first room's run only (every later room is entered square through
  // its doorway, and a travel keeps the frame of the map it was given).
  if (phase_ != Phase::Exploring || roomsStarted_ != 1) p.squareSweepMrad = 0;
  return p;
}

Pose RoomSession::pose() const {
  if ((phase_ == Phase::Exploring || phase_ == Phase::Travelling || phase_ == Phase::Levelling) &&
      stack_.explorer() != nullptr)
    return stack_.explorer()->pose();
  if (phase_ == Phase::Crossing) return crossPose_;
  return idlePose_;
}

void RoomSession::abort() {
  idlePose_ = pose();
  stack_.end();
  phase_ = Phase::Idle;
  outcome_ = Outcome::None;
}

void RoomSession::setPose(const Pose& p) {
  if (phase_ == Phase::Idle) idlePose_ = p;
}

DriveAction RoomSession::exploreRoom(Strategy strategy, const Pose& at, const Doorway* entrance) {
  confinement_.begin(entrance);
  confinement_.hold(stack_.map());
  ++roomsStarted_;
  phase_ = Phase::Exploring;
  outcome_ = Outcome::None;
  last_ = stack_.start(strategy, pilotConfig(), at, Cell{}, &confinement_);
  if (stack_.finished()) return finishExploring();  // nothing to do: over at once
  return last_;
}

DriveAction RoomSession::goTo(Cell target, const Pose& at) {
  outcome_ = Outcome::None;
  if (at.cell == target) {
    idlePose_ = at;
    outcome_ = Outcome::Arrived;
    return DriveAction::done();
  }
  phase_ = Phase::Travelling;
  last_ = stack_.start(Strategy::GoTo, pilotConfig(), at, target);
  if (stack_.finished()) return finishTravelling();  // no way there: over at once
  return last_;
}

DriveAction RoomSession::cross(const RoomExit& exit, Strategy strategy) {
  exit_ = exit;
  crossPose_ = pose();
  crossLeft_ = static_cast<int16_t>(exit.door.depth + 1);
  nextStrategy_ = strategy;
  phase_ = Phase::Crossing;
  outcome_ = Outcome::None;
  stack_.end();
  return crossNext();
}

DriveAction RoomSession::scan() {
  idlePose_ = pose();
  scanNext_ = 0;
  phase_ = Phase::Scanning;
  outcome_ = Outcome::None;
  return DriveAction::read(Sensor::Front);
}

DriveAction RoomSession::stepScanning(const DriveEvent& e) {
  if (e.kind == DriveEvent::Kind::Range) {
    scan_[scanNext_] = e.reading;
    ++travel_.sensorRequests;
    travel_.rawSamples += e.reading.samples;
  }
  if (++scanNext_ < kSensorCount) return DriveAction::read(static_cast<Sensor>(scanNext_));
  phase_ = Phase::Idle;
  outcome_ = Outcome::Scanned;
  return DriveAction::done();
}

DriveAction RoomSession::step(const DriveEvent& e) {
  switch (phase_) {
    case Phase::Exploring: return stepExploring(e);
    case Phase::Travelling: return stepTravelling(e);
    case Phase::Crossing: return stepCrossing(e);
    case Phase::Levelling: return finishCommand();
    case Phase::Scanning: return stepScanning(e);
    case Phase::Idle: break;
  }
  return DriveAction::done();
}

DriveAction RoomSession::stepExploring(const DriveEvent& event) {
  MapLayers& map = stack_.map();
  DriveEvent e = event;
  for (;;) {
    last_ = stack_.step(e);
    confinement_.hold(map);
    if (stack_.finished()) break;
    confinement_.look(map, pose().cell);
    // A move decided just before a doorway was closed meets the closed doorway like a wall.
    if (!confinement_.drivesIntoShut(pose(), last_)) return last_;
    e = DriveEvent::driven(true);
  }
  return finishExploring();
}

DriveAction RoomSession::finishExploring() {
  explore_ += stack_.counters();
  return endRun(Outcome::RoomMapped);
}

DriveAction RoomSession::stepTravelling(const DriveEvent& e) {
  last_ = stack_.step(e);
  if (!stack_.finished()) return last_;
  return finishTravelling();
}

DriveAction RoomSession::finishTravelling() {
  travel_ += stack_.counters();
  const bool arrived = stack_.goTo() != nullptr && stack_.goTo()->arrived();
  if (!arrived) ++travelsNotArrived_;
  return endRun(arrived ? Outcome::Arrived : Outcome::NotArrived);
}

DriveAction RoomSession::endRun(Outcome outcome) {
  const Pilot& pilot = *stack_.pilot();
  // On the axis for what follows (dead-reckoned crossing steps, a new room, the next travel).
  const DriveAction level = pilot.levelling();
  headingVariance_ = pilot.handOverHeadingVariance();
  pilot_.wheels = pilot.wheels();  // what this run learnt of the wheels, the next one starts from
  idlePose_ = stack_.explorer()->pose();
  if (outcome == Outcome::RoomMapped) confinement_.finish(stack_.map());
  pendingOutcome_ = outcome;
  if (level.kind == DriveAction::Kind::Rotate) {
    phase_ = Phase::Levelling;
    return level;
  }
  return finishCommand();
}

DriveAction RoomSession::finishCommand() {
  phase_ = Phase::Idle;
  outcome_ = pendingOutcome_;
  idlePose_ = stack_.explorer() != nullptr ? stack_.explorer()->pose() : idlePose_;
  return DriveAction::done();
}

// The next crossing action: a dead-reckoned turn outward (its error is nothing measures: the
// heading's variance grows), then one-cell drives.
DriveAction RoomSession::crossNext() {
  if (crossPose_.heading != exit_.outward) {
    int eighths = 4;
    if (rotate(crossPose_.heading, 1) == exit_.outward) eighths = 2;
    if (rotate(crossPose_.heading, -1) == exit_.outward) eighths = -2;
    const int64_t sigma =
        static_cast<int64_t>(pilot_.noise.turnMradPerQuarter) * (eighths < 0 ? -eighths : eighths) / 2;
    headingVariance_ += sigma * sigma;
    travel_.turnEighths += static_cast<uint32_t>(eighths < 0 ? -eighths : eighths);
    crossPose_.heading = exit_.outward;
    return DriveAction::rotate(eighths / 2 * kQuarterMrad);
  }
  return DriveAction::drive(static_cast<int32_t>(stack_.config().geometry.cellCm) * 10);
}

DriveAction RoomSession::stepCrossing(const DriveEvent& e) {
  if (e.kind == DriveEvent::Kind::Rotated) return crossNext();
  if (e.kind != DriveEvent::Kind::Driven) return crossNext();
  if (e.blocked) {
    ++travel_.blockedMoves;
    idlePose_ = crossPose_;
    phase_ = Phase::Idle;
    outcome_ = Outcome::CrossBlocked;
    return DriveAction::done();
  }
  ++travel_.cellsMoved;
  crossPose_.cell = advance(crossPose_.cell, crossPose_.heading);
  if (--crossLeft_ > 0) return crossNext();
  // Through: the next room starts here, the doorway behind the robot held shut.
  crossedAt_ = crossPose_;
  const Doorway entrance = intoFrame(exit_.door, crossPose_);
  stack_.map().clear();
  return exploreRoom(nextStrategy_, Pose{}, &entrance);
}

}  // namespace nxtmap
