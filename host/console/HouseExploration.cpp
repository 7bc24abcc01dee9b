#include "host/console/HouseExploration.hpp"

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "host/console/ConsoleCommand.hpp"

namespace nxtmap::console {
namespace {

using Kind = house::HouseOrder::Kind;
constexpr double kCrossBlockedS = 3.0;  // an EnterRoom run, and the brick still idle in its room: blocked
// The brick standing still this long (and over this many statuses: 500 ms apart on the brick, some
// lost on a damaged link) with the order's report not in: the order was dropped on the brick. A
// report late on a damaged link takes seconds, not a minute.
constexpr double kStillS = 60.0;
constexpr uint64_t kStillStatuses = 100;

// The planner as `sim-house` configures it, for the brick at the other end: its pilot's pose range
// and its grid (from its HelloReply, which start() requires).
house::HousePlannerConfig linkPlanner(const link::Session& s) {
  house::HousePlannerConfig c;
  c.poseRangeCm = PilotConfig{}.poseRangeCm;
  c.gridCells = 1 << s.hello()->gridWidthLog2;
  return c;
}

}  // namespace

std::string HouseExploration::start(link::Session& s, double nowS) {
  if (active_) throw ConsoleError("explore house: the house is being mapped already (wait house)");
  if (!s.hello())
    throw ConsoleError("explore house: the brick has not answered yet (its grid and sensor geometry are unknown)");
  geometry_ = protocol::rangeGeometryOf(s.hello()->geometry);
  planner_.emplace(linkPlanner(s), geometry_);
  active_ = true;
  done_ = false;
  stopped_.clear();
  roomsMapped_ = 0;
  startedS_ = nowS_ = nowS;
  room_ = s.status() ? s.status()->roomId : uint16_t{0};
  ++room_;  // a confined explore starts the next room
  return "mapping the house: " + send(s, planner_->start());
}

// An order the brick's decoder would refuse is never sent (Session throws; the planner makes none: its
// openings are cut to the widest doorway an EnterRoom holds): the house stops there, saying why, with
// what it has mapped kept.
std::string HouseExploration::send(link::Session& s, const house::HouseOrder& o) {
  try {
    return sendOrder(s, o);
  } catch (const std::invalid_argument& e) {
    wait_ = Wait::Nothing;
    active_ = false;
    stopped_ = std::string("an order the brick would refuse: ") + e.what();
    return "house stopped: " + stopped_ + "; " + progress() + "\n";
  }
}

std::string HouseExploration::sendOrder(link::Session& s, const house::HouseOrder& o) {
  stillFrom_ = 0;
  switch (o.kind) {
    case Kind::ExploreFirstRoom:
      s.explore(protocol::ExploreMsg{protocol::ExploreStrategy::Frontier, true});
      wait_ = Wait::Room;
      stood_.clear();
      return "the brick maps the room it stands in\n";
    case Kind::Travel: sendTravel(s, o); return "";
    case Kind::Cross: sendCross(s, o); return "";
    case Kind::Scan:
      scanId_ = static_cast<uint16_t>(scanId_ == 0xFFFF ? 1 : scanId_ + 1);
      s.scan(scanId_);
      wait_ = Wait::Scan;
      return "";
    case Kind::Finished: break;
  }
  wait_ = Wait::Nothing;
  active_ = false;
  done_ = true;
  return "the house is mapped: " + progress() + "\n";
}

// The known house around the leg goes to the brick, the robot at its origin, then the goal.
void HouseExploration::sendTravel(link::Session& s, const house::HouseOrder& o) {
  std::vector<CellState> cells;
  for (int y = o.map.minY(); y <= o.map.maxY(); ++y) {
    for (int x = o.map.minX(); x <= o.map.maxX(); ++x)
      cells.push_back(o.map.at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}));
  }
  const Bounds window{static_cast<int16_t>(o.map.minX()), static_cast<int16_t>(o.map.minY()),
                      static_cast<int16_t>(o.map.maxX()), static_cast<int16_t>(o.map.maxY())};
  ++goalId_;
  s.uploadMap(window, cells, transferId_++);
  s.setPose(Pose{});
  s.goTo(goalId_, o.target);
  wait_ = Wait::Goal;
}

void HouseExploration::sendCross(link::Session& s, const house::HouseOrder& o) {
  protocol::EnterRoomMsg m;
  m.roomId = static_cast<uint16_t>(room_ + 1);
  m.strategy = protocol::ExploreStrategy::Frontier;
  m.door = protocol::doorwayMessage(o.exit.door);
  m.outward = o.exit.outward;
  m.inside = o.exit.inside;
  s.setPose(o.at);
  enterSeq_ = s.enterRoom(m);
  ++room_;
  statusesAtAck_ = 0;
  wait_ = Wait::Cross;
  stood_.clear();
  crossSinceS_ = nowS_;
}

house::HouseReport HouseExploration::roomReport(link::Session& s) const {
  house::HouseReport r;
  r.kind = house::HouseReport::Kind::RoomMapped;
  r.pose = s.status()->pose;
  const Bounds b = s.map().bounds();
  r.map = network::RoomMap(b.minX, b.minY, b.width(), b.height());
  s.map().forEach([&](Cell c, CellState st) { r.map.set(c, st); });
  const protocol::RoomExitsMsg& m = *s.roomExits();
  for (uint8_t i = 0; i < m.count; ++i)
    r.exits.push_back(RoomExit{protocol::doorwayOf(m.exits[i].door), m.exits[i].inside, m.exits[i].outward});
  if (s.room() && s.room()->roomId == room_) r.crossedAt = Pose{s.room()->origin, s.room()->heading};
  r.stood = stood_;
  return r;
}

std::optional<house::HouseReport> HouseExploration::arrived(link::Session& s) {
  if (wait_ == Wait::Cross) {
    if (std::optional<house::HouseReport> blocked = crossBlocked(s)) return blocked;
  }
  if (wait_ == Wait::Room) return roomDone(s);
  if (wait_ == Wait::Goal) return goalDone(s);
  if (wait_ == Wait::Scan) return scanDone(s);
  return std::nullopt;
}

// Through the doorway: the brick reports the new room (then the room's end is awaited). Blocked: it
// says it is idle in its old room, in statuses sent after it ran EnterRoom (the second after the
// acknowledgement: the first may have left before), a while after.
std::optional<house::HouseReport> HouseExploration::crossBlocked(link::Session& s) {
  const bool entered = (s.status() && s.status()->roomId == room_) || (s.room() && s.room()->roomId == room_);
  if (statusesAtAck_ == 0 && s.acknowledged(enterSeq_)) {
    statusesAtAck_ = s.statusesReceived() + 1;
    crossSinceS_ = nowS_;
  }
  const bool idleSince =
      statusesAtAck_ != 0 && s.statusesReceived() > statusesAtAck_ && s.status()->mode == protocol::BrickMode::Idle;
  if (entered) wait_ = Wait::Room;
  if (entered || !idleSince || nowS_ - crossSinceS_ <= kCrossBlockedS) return std::nullopt;
  house::HouseReport r;
  r.kind = house::HouseReport::Kind::CrossBlocked;
  r.pose = s.status()->pose;
  --room_;
  return r;
}

// The room's end (its whole map held here) and a Status of the brick done in that room (its pose);
// after a crossing, also the new room's frame (NewRoom, repeated with every Status).
std::optional<house::HouseReport> HouseExploration::roomDone(link::Session& s) const {
  const auto& st = s.status();
  const bool framed = roomsMapped_ == 0 || (s.room() && s.room()->roomId == room_);
  const bool ended = s.roomExits() && s.roomExits()->roomId == room_ && s.roomExits()->end != ExplorerEnd::Running;
  if (!ended || !st || st->roomId != room_ || st->mode != protocol::BrickMode::Done || !framed) return std::nullopt;
  return roomReport(s);
}

// The scan's readings and the pose it was taken at, once the brick reports this scan's id.
std::optional<house::HouseReport> HouseExploration::scanDone(link::Session& s) const {
  if (!s.readings() || s.readings()->scanId != scanId_) return std::nullopt;
  house::HouseReport r;
  r.kind = house::HouseReport::Kind::Scanned;
  r.pose = s.readings()->scanPose;
  for (int i = 0; i < kSensorCount; ++i) r.scan[i] = s.readings()->scan[i];
  return r;
}

// The goal's end and the pose it ended at, from one Status (a Pose message may be older).
std::optional<house::HouseReport> HouseExploration::goalDone(link::Session& s) const {
  const auto& st = s.status();
  if (!s.commandsDone() || !st || st->path.pathId != goalId_) return std::nullopt;
  if (st->path.state != protocol::PathState::Reached && st->path.state != protocol::PathState::Blocked)
    return std::nullopt;
  house::HouseReport r;
  r.kind = st->path.state == protocol::PathState::Reached ? house::HouseReport::Kind::Arrived
                                                          : house::HouseReport::Kind::NotArrived;
  r.pose = st->pose;
  return r;
}

std::string HouseExploration::brickGaveUp(const link::Session& s) {
  const auto& st = s.status();
  if (!st || !s.commandsDone()) return "";
  if (st->mode == protocol::BrickMode::Fault)
    return "the brick stopped its motors (a wheel stalled or was held: its motor safety)";
  if (standingStill(s))
    return "the brick stands still without reporting the order it was given (a button on the brick, or "
           "another console's command, ended it)";
  return "";
}

// Idle or Done, in every Status for a while, with the awaited report not in (a link that is down
// brings no statuses, so it does not count). A crossing has its own rule (crossBlocked).
bool HouseExploration::standingStill(const link::Session& s) {
  const auto& st = s.status();
  const bool still = st->mode == protocol::BrickMode::Idle || st->mode == protocol::BrickMode::Done;
  if (!still || wait_ == Wait::Cross || wait_ == Wait::Nothing) {
    stillFrom_ = 0;
    return false;
  }
  if (stillFrom_ == 0) {
    stillFrom_ = s.statusesReceived();
    stillSinceS_ = nowS_;
  }
  return s.statusesReceived() >= stillFrom_ + kStillStatuses && nowS_ - stillSinceS_ >= kStillS;
}

std::string HouseExploration::poll(link::Session& s, double nowS) {
  if (!active_) return "";
  nowS_ = nowS;
  const std::string why = brickGaveUp(s);
  if (!why.empty()) {
    active_ = false;
    stopped_ = why;
    return "house stopped: " + why + "; " + progress() + "\n";
  }
  noteWhereItStands(s);
  const std::optional<house::HouseReport> r = arrived(s);
  if (!r) return "";
  std::string out;
  if (r->kind == house::HouseReport::Kind::RoomMapped) {
    ++roomsMapped_;
    std::ostringstream o;
    o << "house: room " << roomsMapped_ << " mapped, " << r->exits.size() << " exits; " << progress() << "\n";
    out += o.str();
  }
  return out + send(s, planner_->on(*r));
}

// While the brick maps room_, the cells its statuses put it in (in that room's frame), each once in a row.
void HouseExploration::noteWhereItStands(const link::Session& s) {
  const auto& st = s.status();
  if (wait_ != Wait::Room || !st || st->roomId != room_ || st->mode != protocol::BrickMode::Exploring) return;
  if (stood_.empty() || !(stood_.back() == st->pose.cell)) stood_.push_back(st->pose.cell);
}

int HouseExploration::roomOfRobot() const {
  const network::HouseNetwork& h = planner_->network();
  const Cell b = planner_->belief().cell;
  for (size_t i = h.rooms().size(); i-- > 0;) {
    if (h.rooms()[i].map.isFree(h.rooms()[i].toHouse.inverse().apply(b))) return static_cast<int>(i);
  }
  return h.rooms().empty() ? -1 : static_cast<int>(h.rooms().size()) - 1;
}

std::string HouseExploration::progress() const {
  std::ostringstream o;
  const double s = nowS_ - startedS_;
  o << planner_->network().rooms().size() << " rooms, " << planner_->network().gateways().size() << " gateways, "
    << planner_->exitsLeft() << " exits left, " << std::fixed << std::setprecision(1) << s << " s";
  return o.str();
}

}  // namespace nxtmap::console
