#include "host/console/Console.hpp"

#include <chrono>
#include <sstream>
#include <thread>

#include "host/mapio/MapFiles.hpp"
#include "host/plan/Planner.hpp"
#include "host/report/MapImage.hpp"
#include "host/report/MapText.hpp"

namespace nxtmap::console {

using protocol::PathState;

bool MapView::toMap(Cell c, int& col, int& row) const {
  col = c.x - bounds.minX;
  row = bounds.maxY - c.y;
  return map.inside(col, row);
}

Cell MapView::toCell(int col, int row) const {
  return Cell{static_cast<int16_t>(bounds.minX + col), static_cast<int16_t>(bounds.maxY - row)};
}

MapView viewOf(const link::Session& s, const std::set<std::pair<int, int>>& blocked) {
  MapView v;
  Bounds b = s.map().bounds();
  if (s.pose()) {
    const Cell r = s.pose()->cell;
    if (b.empty()) b = Bounds{r.x, r.y, r.x, r.y};
    b.minX = std::min(b.minX, r.x);
    b.maxX = std::max(b.maxX, r.x);
    b.minY = std::min(b.minY, r.y);
    b.maxY = std::max(b.maxY, r.y);
  }
  v.bounds = b;
  if (b.empty()) return v;
  v.map = mapio::OccupancyMap(b.width(), b.height(), mapio::Occupancy::Unknown);
  s.map().forEach([&](Cell c, CellState st) {
    int col = 0, row = 0;
    if (v.toMap(c, col, row))
      v.map.set(col, row, st == CellState::Free ? mapio::Occupancy::Free : mapio::Occupancy::Occupied);
  });
  for (const auto& [x, y] : blocked) {
    int col = 0, row = 0;
    if (v.toMap(Cell{static_cast<int16_t>(x), static_cast<int16_t>(y)}, col, row))
      v.map.set(col, row, mapio::Occupancy::Occupied);
  }
  if (s.pose()) {
    int col = 0, row = 0;
    if (v.toMap(s.pose()->cell, col, row)) v.robot = plan::MapCell{col, row};
    v.heading = s.pose()->heading;
  }
  return v;
}

Console::Console(link::LinkRunner& runner, std::string linkText) : runner_(runner), linkText_(std::move(linkText)) {
  network::RoomNode first;
  first.name = "room0";
  house_.addRoom(std::move(first));
  placed_.push_back(true);
}

bool Console::waitFor(const std::function<bool()>& done, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    notes_ += poll();  // shown with the command's answer
    if (waiting_) waiting_();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return done();
}

std::string Console::renderMap() const {
  return runner_.with([&](link::Session& s) {
    const MapView v = viewOf(s, blocked_);
    if (v.bounds.empty()) return std::string("(no map yet)\n");
    std::optional<report::RobotMark> robot;
    if (v.robot) {
      static const sim::Heading kHeading[4] = {sim::Heading::N, sim::Heading::E, sim::Heading::S, sim::Heading::W};
      robot = report::RobotMark{v.robot->col, v.robot->row, kHeading[static_cast<int>(v.heading)]};
    }
    return report::renderMapText(
        v.map.width(), v.map.height(),
        [&](int col, int row) {
          switch (v.map.at(col, row)) {
            case mapio::Occupancy::Free: return CellState::Free;
            case mapio::Occupancy::Occupied: return CellState::Occupied;
            default: return CellState::Unknown;
          }
        },
        robot);
  });
}

std::string Console::statusLine() const {
  const std::string state = runner_.state();
  return runner_.with([&](link::Session& s) {
    static const char* kModes[] = {"idle", "exploring", "following a path", "done exploring", "fault"};
    std::ostringstream o;
    o << state;
    if (s.status()) o << " | robot " << kModes[static_cast<int>(s.status()->mode)];
    o << " | map " << s.map().known() << " cells";
    if (goal_.active) o << " | goal " << goal_.path.size() << "-cell route";
    return o.str();
  });
}

std::vector<Cell> Console::planTo(Cell target, std::string& why) const {
  return runner_.with([&](link::Session& s) {
    const MapView v = viewOf(s, blocked_);
    std::vector<Cell> cells;
    if (!v.robot) {
      why = "the robot's position is not known yet";
      return cells;
    }
    int col = 0, row = 0;
    if (!v.toMap(target, col, row)) {
      why = "the goal is outside the map";
      return cells;
    }
    auto planner = plan::makePlanner(plan::Algorithm::AStar);
    const plan::PlanResult r = planner->plan(v.map, *v.robot, plan::MapCell{col, row});
    if (!r.found()) {
      why = "no known free route from the robot to the goal";
      return cells;
    }
    for (const plan::MapCell& m : r.path) cells.push_back(v.toCell(m.col, m.row));
    return cells;
  });
}

void Console::sendSegment() {
  const size_t from = goal_.sentUpTo;
  const size_t to = std::min(goal_.path.size() - 1, from + kSegmentCells - 1);
  std::vector<Cell> segment(goal_.path.begin() + static_cast<long>(from),
                            goal_.path.begin() + static_cast<long>(to) + 1);
  goal_.pathId = nextPathId_++;
  goal_.sentUpTo = to;
  runner_.with([&](link::Session& s) { return s.followPath(segment, goal_.pathId); });
}

std::string Console::startGoal(Cell target, const std::string& what) {
  std::string why;
  const std::vector<Cell> path = planTo(target, why);
  if (path.empty()) throw ConsoleError(what + ": " + why + "; nothing sent");
  route_.active = false;
  return startPath(path, what);
}

std::string Console::startPath(const std::vector<Cell>& path, const std::string& what) {
  goal_ = Goal{};
  goal_.target = path.back();
  goal_.path = path;
  goal_.active = true;
  if (path.size() == 1) {
    goal_.active = false;
    goal_.outcome = "reached";
    return "the robot is already there\n";
  }
  sendSegment();
  std::ostringstream o;
  o << "driving to " << what << ": " << path.size() - 1 << " moves\n";
  return o.str();
}

std::string Console::poll() {
  std::string out;
  out.swap(notes_);
  if (!runner_.with([](link::Session& s) { return s.takeUnconfirmed(); }).empty()) {
    out +=
        "the brick did not know this console any more (it restarted, or another console talked to it): the "
        "command sent last may not have run; it is not sent again\n";
  }
  out += pollRooms();
  out += pollUpload();
  out += pollGoal();
  out += pollRoute();
  return out;
}

std::string Console::pollGoal() {
  if (!goal_.active) return "";
  const std::optional<protocol::PathProgressMsg> p = runner_.with([](link::Session& s) { return s.pathProgress(); });
  if (!p || p->pathId != goal_.pathId) return "";
  if (p->state == PathState::Reached) {
    if (goal_.sentUpTo + 1 >= goal_.path.size()) {
      goal_.active = false;
      goal_.outcome = "reached";
      return "goal reached\n";
    }
    sendSegment();
    return "";
  }
  if (p->state == PathState::Blocked || p->state == PathState::Aborted) {
    if (p->state == PathState::Blocked) blocked_.insert({p->at.x, p->at.y});
    if (++goal_.replans > 8) {
      goal_.active = false;
      goal_.outcome = "unreachable: blocked too often";
      return "goal given up: the way was blocked 8 times\n";
    }
    std::string why;
    const std::vector<Cell> path = planTo(goal_.target, why);
    if (path.empty()) {
      goal_.active = false;
      goal_.outcome = "unreachable: " + why;
      return "goal given up: " + why + "\n";
    }
    goal_.path = path;
    goal_.sentUpTo = 0;
    sendSegment();
    return "blocked at (" + std::to_string(p->at.x) + "," + std::to_string(p->at.y) + "): replanned\n";
  }
  return "";
}

std::string Console::execute(const ConsoleCommand& c) {
  const std::string out = executeCommand(c);
  std::string notes;
  notes.swap(notes_);
  return notes + out;
}

std::string Console::executeCommand(const ConsoleCommand& c) {
  using K = ConsoleCommand::Kind;
  const bool connected = runner_.with([](link::Session& s) { return s.connected(); });
  auto needLink = [&](const char* what) {
    if (!connected)
      throw ConsoleError(std::string(what) + ": the brick is not connected (" + runner_.state() + "); nothing sent");
  };
  switch (c.kind) {
    case K::Empty: return "";
    case K::Help: return consoleHelp();
    case K::Quit: quit_ = true; return "";
    case K::Explore:
      needLink("explore");
      goal_.active = false;
      route_.active = false;
      runner_.with([](link::Session& s) { return s.explore(); });
      return "exploring\n";
    case K::Stop:
      needLink("stop");
      goal_.active = false;
      route_.active = false;
      runner_.with([](link::Session& s) { return s.stop(); });
      return "stopping\n";
    case K::Goto: {
      needLink("goto");
      const MapView v = runner_.with([&](link::Session& s) { return viewOf(s, blocked_); });
      const std::string where = "(" + std::to_string(c.col) + "," + std::to_string(c.row) + ")";
      if (v.bounds.empty() || !v.map.inside(c.col, c.row)) {
        throw ConsoleError("goto " + where + ": outside the map (" + std::to_string(v.map.width()) + " x " +
                           std::to_string(v.map.height()) + " cells); nothing sent");
      }
      const mapio::Occupancy o = v.map.at(c.col, c.row);
      if (o == mapio::Occupancy::Occupied)
        throw ConsoleError("goto " + where + ": that cell is an obstacle; nothing sent");
      if (o == mapio::Occupancy::Unknown)
        throw ConsoleError("goto " + where + ": that cell is unexplored; nothing sent");
      return startGoal(v.toCell(c.col, c.row), "goto " + where);
    }
    case K::GotoNear: {
      needLink("goto near");
      const auto it = labels().find(c.name);
      if (it == labels().end())
        throw ConsoleError("goto near " + c.name + ": no such label (see label NAME C R); nothing sent");
      // The nearest free cell next to the labelled one, by route length.
      const MapView v = runner_.with([&](link::Session& s) { return viewOf(s, blocked_); });
      int col = 0, row = 0;
      if (!v.toMap(it->second, col, row) || !v.robot)
        throw ConsoleError("goto near " + c.name + ": the label is outside the map; nothing sent");
      auto planner = plan::makePlanner(plan::Algorithm::AStar);
      std::optional<Cell> best;
      double bestLength = 0;
      for (int dr = -1; dr <= 1; ++dr) {
        for (int dc = -1; dc <= 1; ++dc) {
          if ((dr == 0 && dc == 0) || !v.map.isFree(col + dc, row + dr)) continue;
          const plan::PlanResult r = planner->plan(v.map, *v.robot, plan::MapCell{col + dc, row + dr});
          if (r.found() && (!best || r.length < bestLength)) {
            best = v.toCell(col + dc, row + dr);
            bestLength = r.length;
          }
        }
      }
      if (!best) throw ConsoleError("goto near " + c.name + ": no reachable free cell next to it; nothing sent");
      return startGoal(*best, "near " + c.name);
    }
    case K::Label: {
      if (!mapio::OccupancyMap::validLabelName(c.name)) {
        throw ConsoleError("label " + c.name + ": a name is 1..64 letters, digits, _ or -, starting with a letter");
      }
      const MapView v = runner_.with([&](link::Session& s) { return viewOf(s, blocked_); });
      if (v.bounds.empty() || !v.map.inside(c.col, c.row))
        throw ConsoleError("label " + c.name + ": the cell is outside the map");
      labels()[c.name] = v.toCell(c.col, c.row);
      return "label " + c.name + " at (" + std::to_string(c.col) + "," + std::to_string(c.row) + ")\n";
    }
    case K::Rooms: return roomsText();
    case K::Route: needLink("route"); return startRoute(c);
    case K::Save:
      if (c.name.size() > 5 && c.name.substr(c.name.size() - 5) == ".yaml") return saveRoom(c.name);
      return saveHouse(c.name);
    case K::Export: {
      const MapView v = runner_.with([&](link::Session& s) { return viewOf(s, blocked_); });
      if (v.bounds.empty()) throw ConsoleError("export: there is no map yet");
      const int px = 8;
      report::RgbImage img;
      img.width = v.map.width() * px;
      img.height = v.map.height() * px;
      img.rgb.assign(static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 3, 0);
      for (int row = 0; row < v.map.height(); ++row) {
        for (int col = 0; col < v.map.width(); ++col) {
          const mapio::Occupancy o = v.map.at(col, row);
          const uint8_t g = o == mapio::Occupancy::Free ? 255 : (o == mapio::Occupancy::Occupied ? 0 : 160);
          img.fill(col * px, row * px, px, px, g, g, g);
        }
      }
      if (v.robot) img.fill(v.robot->col * px + 1, v.robot->row * px + 1, px - 2, px - 2, 220, 30, 30);
      std::string error;
      if (!report::writePng(c.name, img, error)) throw ConsoleError("export: " + error);
      return "exported " + c.name + "\n";
    }
    case K::Status:
      return runner_.with([&](link::Session& s) {
        std::ostringstream o;
        o << "link: " << linkText_ << ", " << (s.connected() ? "connected" : "not connected") << "\n";
        if (s.status()) {
          static const char* kModes[] = {"idle", "exploring", "following a path", "done exploring", "fault"};
          o << "robot: " << kModes[static_cast<int>(s.status()->mode)] << " at (" << s.status()->pose.cell.x << ","
            << s.status()->pose.cell.y << ") battery " << s.status()->batteryMillivolts << " mV\n";
        }
        o << "map: " << s.map().known() << " known cells, epoch " << s.map().epoch() << "\n";
        if (s.brickCounters()) {
          const auto& k = *s.brickCounters();
          o << "brick: " << k.explorer.sensorRequests << " readings, " << k.explorer.cellsMoved << " cells moved, "
            << k.explorer.turnEighths << " turn eighths, " << k.link.commandsRun << " commands run, "
            << k.link.duplicates << " duplicates ignored, " << k.link.retransmits << " map retransmissions\n";
        }
        const auto& pc = s.counters();
        o << "pc: " << pc.bytesIn << " bytes in, " << pc.deltasApplied << " map deltas, " << pc.commandsAcknowledged
          << " commands acknowledged, " << pc.commandRetries << " resent, " << s.decoderCounters().skipped
          << " noise bytes skipped, " << pc.connects << " connects\n";
        if (!goal_.outcome.empty() || goal_.active)
          o << "goal: " << (goal_.active ? "on the way" : goal_.outcome) << "\n";
        return o.str();
      });
    case K::Battery: {
      needLink("battery");
      runner_.with([](link::Session& s) {
        s.requestBattery();
        s.requestLegoBattery();
        return 0;
      });
      const bool got = waitFor(
          [&] {
            return runner_.with([](link::Session& s) {
              return s.batteryMillivolts().has_value() && s.legoBatteryMillivolts().has_value();
            });
          },
          3.0);
      const auto mv = runner_.with([](link::Session& s) { return s.batteryMillivolts(); });
      const auto lego = runner_.with([](link::Session& s) { return s.legoBatteryMillivolts(); });
      if (!got && !mv && !lego) throw ConsoleError("battery: no answer from the brick within 3 s");
      std::ostringstream o;
      o << "battery: " << (mv ? std::to_string(*mv) : std::string("?"))
        << " mV (LEGO GET_BATTERY_LEVEL: " << (lego ? std::to_string(*lego) : std::string("no answer")) << ")\n";
      return o.str();
    }
    case K::Map: return renderMap();
    case K::Wait: {
      bool ok = false;
      if (c.name == "explored") {
        ok = waitFor(
            [&] {
              return runner_.with(
                  [](link::Session& s) { return s.status() && s.status()->mode == protocol::BrickMode::Done; });
            },
            c.seconds);
      } else {
        if (!goal_.active && !route_.active && goal_.outcome.empty())
          throw ConsoleError("wait goal: no goal was given");
        ok = waitFor([&] { return !goal_.active && !route_.active; }, c.seconds);
        if (ok && goal_.outcome != "reached") throw ConsoleError("goal not reached: " + goal_.outcome);
      }
      if (!ok)
        throw ConsoleError("wait " + c.name + ": still not there after " + std::to_string(static_cast<int>(c.seconds)) +
                           " s");
      return c.name == "explored" ? "exploring done\n" : "done waiting: goal reached\n";
    }
  }
  return "";
}

}  // namespace nxtmap::console
