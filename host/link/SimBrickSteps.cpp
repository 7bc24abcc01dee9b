// The stand-in brick's time: each step carries out the commands the link brought, then one action at a time of
// the house, the explorer or the path followed, on the simulated robot, at the pace SimBrickConfig gives.
#include "host/link/SimBrick.hpp"
#include "host/mapping/SimDrive.hpp"

namespace nxtmap::link {

using namespace protocol;

bool SimBrick::worldBlocked(Cell c) const {
  int col = 0, row = 0;
  frame_.toWorld(c, col, row);
  return world_.blocked(col, row);
}

void SimBrick::followOne() {
  const Cell from = restPose_.cell;
  const Cell to = pathMsg_.cellAt(static_cast<uint16_t>(path_.reached + 1));
  const bool diagonal = from.x != to.x && from.y != to.y;
  const bool cornerBlocked = diagonal && (worldBlocked(Cell{to.x, from.y}) || worldBlocked(Cell{from.x, to.y}));
  if (worldBlocked(to) || cornerBlocked) {
    path_.state = PathState::Blocked;
    path_.at = to;
    mode_ = BrickMode::Idle;
    return;
  }
  restPose_.cell = to;
  if (to.y > from.y)
    restPose_.heading = Dir::North;
  else if (to.y < from.y)
    restPose_.heading = Dir::South;
  else if (to.x > from.x)
    restPose_.heading = Dir::East;
  else
    restPose_.heading = Dir::West;
  // The simulated robot goes along, onto the cell's centre.
  int col = 0, row = 0;
  frame_.toWorld(to, col, row);
  const sim::Vec2 centre = robot_.frame().toPlane(sim::Vec2(col, row));
  (void)robot_.setPose(centre.x(), centre.y(),
                       robot_.frame().headingDeg + 90.0 * static_cast<int>(frame_.toWorld(restPose_.heading)));
  ++path_.reached;
  path_.at = to;
  if (path_.reached + 1 >= pathMsg_.count) {
    path_.state = PathState::Reached;
    mode_ = BrickMode::Idle;
  }
}

void SimBrick::exploreOne() {
  if (!stack_.running() || stack_.finished()) {
    mode_ = BrickMode::Done;
    return;
  }
  // The core's thinking slices cost no robot time here (the brick spends about 1 ms on each).
  do {
    pending_ = stack_.step(mapping::carryOutOnRobot(robot_, pending_, stack_.config().geometry));
  } while (!stack_.finished() && pending_.kind == DriveAction::Kind::Think);
  if (calibrating_ && (stack_.pilot()->explorerStarted() || stack_.finished())) return endCalibration();
  if (stack_.finished() || pending_.kind == DriveAction::Kind::Done) mode_ = BrickMode::Done;
}

void SimBrick::houseOne() {
  // The core's thinking slices cost no robot time here (the brick spends about 1 ms on each).
  do {
    pending_ = house_.step(mapping::carryOutOnRobot(robot_, pending_, stack_.config().geometry));
    if (house_.takeMapRestart()) {  // through the doorway: the next room's frame starts here
      newRoomFrame(house_.session().crossedAt());
      link_.mapRestarted();
      roomId_ = house_.roomId();
    }
  } while (house_.running() && pending_.kind == DriveAction::Kind::Think);
  mode_ = house_.mode();
}

void SimBrick::step(uint32_t nowMs) {
  Command c;
  while (link_.nextCommand(c)) carryOut(c);
  while (nowMs >= nextActionMs_) {
    if (house_.active() && house_.running()) {
      houseOne();
      nextActionMs_ += config_.actionMs;
    } else if (mode_ == BrickMode::Exploring) {
      exploreOne();
      nextActionMs_ += config_.actionMs;
    } else if (mode_ == BrickMode::Following) {
      followOne();
      nextActionMs_ += config_.cellMs;
    } else {
      nextActionMs_ = nowMs + 1;
    }
  }
}

}  // namespace nxtmap::link
