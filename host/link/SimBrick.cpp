#include "host/link/SimBrick.hpp"

namespace nxtmap::link {

using namespace protocol;

SimBrick::SimBrick(const sim::World& world, const SimBrickConfig& config)
    : config_(config),
      run_(world, config.run),
      shadow_(packedBytes(run_.explorer().map().grid().capacityWidth(), run_.explorer().map().grid().capacityHeight(), 2)),
      link_(run_.explorer().map().grid(), shadow_.data(), config.link) {}

void SimBrick::receive(const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) link_.receive(data[i]);
}

Pose SimBrick::pose() const { return pathPose_ ? *pathPose_ : run_.explorer().pose(); }

BrickReport SimBrick::report() const {
  BrickReport r;
  r.mode = mode_;
  r.pose = pose();
  r.counters = run_.counters();
  r.batteryMillivolts = config_.batteryMillivolts;
  r.path = path_;
  return r;
}

std::vector<uint8_t> SimBrick::transmit(uint32_t nowMs, size_t maxBytes) {
  const BrickReport r = report();
  Frame f;
  while (txQueue_.size() < maxBytes && link_.transmit(nowMs, r, f)) txQueue_.insert(txQueue_.end(), f.bytes, f.bytes + f.size);
  const size_t n = std::min(maxBytes, txQueue_.size());
  std::vector<uint8_t> out(txQueue_.begin(), txQueue_.begin() + static_cast<long>(n));
  txQueue_.erase(txQueue_.begin(), txQueue_.begin() + static_cast<long>(n));
  return out;
}

void SimBrick::linkLost() {
  link_.linkLost();
  txQueue_.clear();
}

void SimBrick::carryOut(const Command& c) {
  executed_.push_back(c.seq);
  switch (c.kind) {
    case CommandKind::Explore:
      pathPose_.reset();
      mode_ = run_.finished() ? BrickMode::Done : BrickMode::Exploring;
      break;
    case CommandKind::Stop:
      if (mode_ == BrickMode::Following) path_.state = PathState::Aborted;
      mode_ = BrickMode::Idle;
      break;
    case CommandKind::FollowPath:
      pathMsg_ = c.path;
      path_ = PathProgressMsg{c.path.pathId, 0, PathState::Following, c.path.start};
      if (c.path.start != pose().cell) {
        path_.state = PathState::Aborted;  // the path must start where the robot stands
        mode_ = BrickMode::Idle;
        break;
      }
      pathPose_ = pose();
      mode_ = BrickMode::Following;
      if (c.path.count == 1) {
        path_.state = PathState::Reached;
        mode_ = BrickMode::Idle;
      }
      break;
    case CommandKind::MapChunk:
      ++mapChunks_;
      break;
  }
}

bool SimBrick::worldBlocked(Cell c) const {
  int col = 0, row = 0;
  run_.frame().toWorld(c, col, row);
  return !run_.world().inside(col, row) || run_.world().blocked(col, row);
}

void SimBrick::followOne() {
  const Cell from = pathPose_->cell;
  const Cell to = pathMsg_.cellAt(static_cast<uint16_t>(path_.reached + 1));
  const bool diagonal = from.x != to.x && from.y != to.y;
  const bool cornerBlocked = diagonal && (worldBlocked(Cell{to.x, from.y}) || worldBlocked(Cell{from.x, to.y}));
  if (worldBlocked(to) || cornerBlocked) {
    path_.state = PathState::Blocked;
    path_.at = to;
    mode_ = BrickMode::Idle;
    return;
  }
  pathPose_->cell = to;
  if (to.y > from.y) pathPose_->heading = Dir::North;
  else if (to.y < from.y) pathPose_->heading = Dir::South;
  else if (to.x > from.x) pathPose_->heading = Dir::East;
  else pathPose_->heading = Dir::West;
  ++path_.reached;
  path_.at = to;
  if (path_.reached + 1 >= pathMsg_.count) {
    path_.state = PathState::Reached;
    mode_ = BrickMode::Idle;
  }
}

void SimBrick::step(uint32_t nowMs) {
  Command c;
  while (link_.nextCommand(c)) carryOut(c);
  while (nowMs >= nextActionMs_) {
    if (mode_ == BrickMode::Exploring) {
      bool more = run_.step();
      // The core's thinking slices cost no robot time here (the brick spends about 1 ms on each).
      while (more && run_.lastAction().kind == DriveAction::Kind::Think) more = run_.step();
      if (!more) mode_ = BrickMode::Done;
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
