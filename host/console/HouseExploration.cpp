#include "host/console/HouseExploration.hpp"

#include <iomanip>
#include <sstream>

#include "host/console/ConsoleCommand.hpp"

namespace nxtmap::console {
namespace {

using Kind = house::HouseOrder::Kind;
constexpr double kCrossBlockedS = 3.0;  // an EnterRoom run, and the brick still idle in its room: blocked

// The planner without a scan over the link (see the header).
house::HousePlannerConfig linkPlanner() {
  house::HousePlannerConfig c;
  c.relocaliseCells = 0;
  c.anchorStart = false;
  return c;
}

protocol::DoorwayMsg doorwayMessage(const Doorway& d) {
  protocol::DoorwayMsg m;
  m.first = d.first;
  m.width = static_cast<uint8_t>(d.width);
  m.depth = static_cast<uint8_t>(d.depth);
  m.alongX = d.alongX;
  return m;
}

Doorway doorwayOf(const protocol::DoorwayMsg& m) {
  Doorway d;
  d.first = m.first;
  d.width = m.width;
  d.depth = m.depth;
  d.alongX = m.alongX;
  return d;
}

}  // namespace

HouseExploration::HouseExploration(link::LinkRunner& runner) : runner_(runner) {}

std::string HouseExploration::start() {
  if (active_) throw ConsoleError("explore house: the house is being mapped already (wait house)");
  planner_.emplace(linkPlanner(), RangeGeometry{});
  active_ = true;
  done_ = false;
  roomsMapped_ = 0;
  started_ = std::chrono::steady_clock::now();
  room_ = runner_.with([](link::Session& s) { return s.status() ? s.status()->roomId : uint16_t{0}; });
  ++room_;  // a confined explore starts the next room
  return "mapping the house: " + send(planner_->start());
}

std::string HouseExploration::send(const house::HouseOrder& o) {
  switch (o.kind) {
    case Kind::ExploreFirstRoom:
      runner_.with([](link::Session& s) {
        return s.explore(protocol::ExploreMsg{protocol::ExploreStrategy::Frontier, true});
      });
      wait_ = Wait::Room;
      return "the brick maps the room it stands in\n";
    case Kind::Travel: {
      std::vector<CellState> cells;
      for (int y = o.map.minY(); y <= o.map.maxY(); ++y) {
        for (int x = o.map.minX(); x <= o.map.maxX(); ++x)
          cells.push_back(o.map.at(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}));
      }
      const Bounds window{static_cast<int16_t>(o.map.minX()), static_cast<int16_t>(o.map.minY()),
                          static_cast<int16_t>(o.map.maxX()), static_cast<int16_t>(o.map.maxY())};
      ++goalId_;
      runner_.with([&](link::Session& s) {
        s.uploadMap(window, cells, transferId_++);
        s.setPose(Pose{});
        return s.goTo(goalId_, o.target);
      });
      wait_ = Wait::Goal;
      return "";
    }
    case Kind::Cross: {
      ++room_;
      protocol::EnterRoomMsg m;
      m.roomId = room_;
      m.strategy = protocol::ExploreStrategy::Frontier;
      m.door = doorwayMessage(o.exit.door);
      m.outward = o.exit.outward;
      m.inside = o.exit.inside;
      runner_.with([&](link::Session& s) {
        s.setPose(o.at);
        return s.enterRoom(m);
      });
      wait_ = Wait::Cross;
      crossSince_ = std::chrono::steady_clock::now();
      return "";
    }
    case Kind::Scan:  // never asked for: relocaliseCells is 0 over the link
    case Kind::Finished: break;
  }
  wait_ = Wait::Nothing;
  active_ = false;
  done_ = true;
  return "the house is mapped: " + progress() + "\n";
}

house::HouseReport HouseExploration::roomReport() const {
  return runner_.with([&](link::Session& s) {
    house::HouseReport r;
    r.kind = house::HouseReport::Kind::RoomMapped;
    r.pose = s.pose() ? *s.pose() : Pose{};
    const Bounds b = s.map().bounds();
    r.map = network::RoomMap(b.minX, b.minY, b.width(), b.height());
    s.map().forEach([&](Cell c, CellState st) { r.map.set(c, st); });
    const protocol::RoomExitsMsg& m = *s.roomExits();
    for (uint8_t i = 0; i < m.count; ++i)
      r.exits.push_back(RoomExit{doorwayOf(m.exits[i].door), m.exits[i].inside, m.exits[i].outward});
    if (s.room() && s.room()->roomId == room_) r.crossedAt = Pose{s.room()->origin, s.room()->heading};
    return r;
  });
}

std::optional<house::HouseReport> HouseExploration::arrived() {
  if (wait_ == Wait::Cross) {
    const auto [entered, idle, pose] = runner_.with([&](link::Session& s) {
      const bool in = s.status() && s.status()->roomId == room_;
      const bool still = s.commandsDone() && s.status() && s.status()->mode == protocol::BrickMode::Idle;
      return std::make_tuple(in, still, s.pose() ? *s.pose() : Pose{});
    });
    if (entered) wait_ = Wait::Room;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - crossSince_).count();
    if (!entered && idle && s > kCrossBlockedS) {
      house::HouseReport r;
      r.kind = house::HouseReport::Kind::CrossBlocked;
      r.pose = pose;
      --room_;
      return r;
    }
  }
  if (wait_ == Wait::Room) {
    const bool mapped = runner_.with([&](link::Session& s) {
      return s.roomExits() && s.roomExits()->roomId == room_ && s.roomExits()->end != ExplorerEnd::Running;
    });
    if (mapped) return roomReport();
  }
  if (wait_ == Wait::Goal) {
    return runner_.with([&](link::Session& s) -> std::optional<house::HouseReport> {
      const auto& p = s.pathProgress();
      if (!s.commandsDone() || !p || p->pathId != goalId_) return std::nullopt;
      if (p->state != protocol::PathState::Reached && p->state != protocol::PathState::Blocked) return std::nullopt;
      house::HouseReport r;
      r.kind = p->state == protocol::PathState::Reached ? house::HouseReport::Kind::Arrived
                                                        : house::HouseReport::Kind::NotArrived;
      r.pose = s.pose() ? *s.pose() : Pose{};
      return r;
    });
  }
  return std::nullopt;
}

std::string HouseExploration::poll() {
  if (!active_) return "";
  const std::optional<house::HouseReport> r = arrived();
  if (!r) return "";
  std::string out;
  if (r->kind == house::HouseReport::Kind::RoomMapped) {
    ++roomsMapped_;
    std::ostringstream o;
    o << "house: room " << roomsMapped_ << " mapped, " << r->exits.size() << " exits; " << progress() << "\n";
    out += o.str();
  }
  return out + send(planner_->on(*r));
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
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  o << planner_->network().rooms().size() << " rooms, " << planner_->network().gateways().size() << " gateways, "
    << planner_->exitsLeft() << " exits left, " << std::fixed << std::setprecision(1) << s << " s";
  return o.str();
}

}  // namespace nxtmap::console
