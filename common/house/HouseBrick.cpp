#include "common/house/HouseBrick.hpp"
#include "common/check/CodeSize.hpp"

namespace nxtmap {
namespace {

Strategy strategyOf(protocol::ExploreStrategy s) {
  return s == protocol::ExploreStrategy::Propagation ? Strategy::Propagation : Strategy::Frontier;
}

}  // namespace

NXTMAP_RUN_ONCE HouseBrick::HouseBrick(ExplorerStack& stack, RoomConfinement& confinement, const PilotConfig& pilot)
    : stack_(stack), confinement_(confinement), session_(stack, confinement, pilot) {}

DriveAction HouseBrick::explore(const protocol::ExploreMsg& how, const Pose& here, uint16_t roomId) {
  abort();
  stack_.map().clear();
  mapRestart_ = true;
  fromRoom_ = roomId;
  roomId_ = static_cast<uint16_t>(roomId + 1);
  origin_ = here;
  active_ = true;
  goal_ = protocol::PathProgressMsg{};
  readings_.scanId = 0;  // a new house: no scan in it yet
  resetExits();
  const DriveAction a = session_.exploreRoom(strategyOf(how.strategy), Pose{}, nullptr);
  roomsSeen_ = session_.roomsStarted();
  if (a.kind == DriveAction::Kind::Done) updateExits();  // nothing to map: the room is done at once
  updateReadings();
  return a;
}

DriveAction HouseBrick::goTo(const protocol::GoToMsg& goal, const Pose& here) {
  abort();
  active_ = true;
  goal_ = protocol::PathProgressMsg{goal.goalId, 0, protocol::PathState::Following, here.cell};
  const DriveAction a = session_.goTo(goal.target, here);
  if (a.kind == DriveAction::Kind::Done) {  // over at once: already there, or no way there
    goal_.state = session_.outcome() == RoomSession::Outcome::Arrived ? protocol::PathState::Reached
                                                                      : protocol::PathState::Blocked;
    goal_.at = session_.pose().cell;
  }
  updateReadings();
  return a;
}

DriveAction HouseBrick::enterRoom(const protocol::EnterRoomMsg& m, const Pose& here) {
  abort();
  active_ = true;
  pendingRoom_ = m.roomId;
  session_.setPose(Pose{m.inside, here.heading});
  RoomExit exit;
  exit.door = protocol::doorwayOf(m.door);
  exit.inside = m.inside;
  exit.outward = m.outward;
  roomsSeen_ = session_.roomsStarted();
  const DriveAction a = session_.cross(exit, strategyOf(m.strategy));
  updateReadings();
  return a;
}

DriveAction HouseBrick::scan(const protocol::ScanMsg& m, const Pose& here) {
  abort();
  active_ = true;
  session_.setPose(here);
  scanId_ = m.scanId;
  const DriveAction a = session_.scan();
  updateReadings();
  return a;
}

DriveAction HouseBrick::step(const DriveEvent& e) {
  const DriveAction a = session_.step(e);
  if (session_.roomsStarted() != roomsSeen_) noteNewRoom();
  if (a.kind == DriveAction::Kind::Done) over();
  updateReadings();
  return a;
}

void HouseBrick::over() {
  switch (session_.outcome()) {
    case RoomSession::Outcome::Arrived:
    case RoomSession::Outcome::NotArrived:
      goal_.state = session_.outcome() == RoomSession::Outcome::Arrived ? protocol::PathState::Reached
                                                                        : protocol::PathState::Blocked;
      goal_.at = session_.pose().cell;
      break;
    case RoomSession::Outcome::RoomMapped: updateExits(); break;
    default: break;
  }
}

void HouseBrick::abort() {
  if (!session_.busy()) return;
  session_.abort();
  if (goal_.state == protocol::PathState::Following) goal_.state = protocol::PathState::Aborted;
}

void HouseBrick::noteNewRoom() {
  roomsSeen_ = session_.roomsStarted();
  mapRestart_ = true;
  fromRoom_ = roomId_;
  roomId_ = pendingRoom_;
  origin_ = session_.crossedAt();
  resetExits();
}

void HouseBrick::resetExits() {
  exits_.roomId = roomId_;
  exits_.end = ExplorerEnd::Running;
  exits_.count = 0;
}

void HouseBrick::updateExits() {
  const Explorer* explorer = stack_.explorer();
  exits_.end = explorer != nullptr ? explorer->end() : ExplorerEnd::Complete;
  exits_.count = 0;
  for (uint8_t i = 0; i < confinement_.exitCount() && exits_.count < protocol::kMaxRoomExits; ++i) {
    const RoomExit& x = confinement_.exit(i);
    protocol::RoomExitMsg& m = exits_.exits[exits_.count++];
    m.door = protocol::doorwayMessage(x.door);
    m.inside = x.inside;
    m.outward = x.outward;
  }
}

void HouseBrick::updateReadings() {
  protocol::ReadingsMsg& m = readings_;
  if (scanId_ != 0 && session_.outcome() == RoomSession::Outcome::Scanned) {
    m.scanId = scanId_;
    m.scanPose = session_.pose();
    for (int i = 0; i < kSensorCount; ++i) m.scan[i] = session_.scanReading(static_cast<Sensor>(i));
    scanId_ = 0;
  }
}

bool HouseBrick::takeMapRestart() {
  const bool r = mapRestart_;
  mapRestart_ = false;
  return r;
}

protocol::BrickMode HouseBrick::mode() const {
  switch (session_.phase()) {
    case RoomSession::Phase::Travelling: return protocol::BrickMode::Following;
    case RoomSession::Phase::Idle: break;
    default: return protocol::BrickMode::Exploring;
  }
  return session_.outcome() == RoomSession::Outcome::RoomMapped ? protocol::BrickMode::Done : protocol::BrickMode::Idle;
}

void HouseBrick::fill(protocol::BrickReport& r) const {
  r.roomId = roomId_;
  r.fromRoom = fromRoom_;
  r.roomOrigin = origin_.cell;
  r.roomHeading = origin_.heading;
  r.roomEntry = Cell{0, 0};
  if (goal_.state != protocol::PathState::None) r.path = goal_;
  r.exits = &exits_;
  r.readings = &readings_;
}

}  // namespace nxtmap
