#include "host/console/Console.hpp"

#include <chrono>
#include <thread>

#include "host/console/StatusText.hpp"

namespace nxtmap::console {
namespace {

using K = ConsoleCommand::Kind;

ConsoleError stillWaiting(const ConsoleCommand& c) {
  return ConsoleError("wait " + c.name + ": still not there after " + std::to_string(static_cast<int>(c.seconds)) +
                      " s");
}

}  // namespace

// The command table. House-session commands (rooms, route, save; later explore house, wait house) sit
// together at the end: a new command is a ConsoleCommand kind, a row here and a short handler.
const Console::Command Console::kCommands[] = {
    {K::Empty, nullptr, &Console::empty},
    {K::Help, nullptr, &Console::help},
    {K::Quit, nullptr, &Console::leave},
    {K::Explore, "explore", &Console::explore},
    {K::ExploreHouse, "explore house", &Console::exploreHouse},
    {K::Stop, "stop", &Console::stop},
    {K::Calibrate, "calibrate", &Console::calibrate},
    {K::Goto, "goto", &Console::gotoCell},
    {K::GotoNear, "goto near", &Console::gotoNear},
    {K::Label, nullptr, &Console::label},
    {K::Export, nullptr, &Console::exportPicture},
    {K::Status, nullptr, &Console::status},
    {K::Battery, "battery", &Console::battery},
    {K::Map, nullptr, &Console::map},
    {K::Wait, nullptr, &Console::wait},
    // The house session.
    {K::Rooms, nullptr, &Console::rooms},
    {K::Route, "route", &Console::route},
    {K::Save, nullptr, &Console::save},
};

Console::Console(link::LinkRunner& runner, std::string linkText)
    : runner_(runner),
      linkText_(std::move(linkText)),
      goals_(runner),
      house_(runner),
      route_(runner, house_, goals_),
      exploration_() {}

std::string Console::execute(const ConsoleCommand& c) {
  std::string out;
  for (const Command& command : kCommands) {
    if (command.kind != c.kind) continue;
    if (command.needsLink && !runner_.with([](link::Session& s) { return s.connected(); })) {
      throw ConsoleError(std::string(command.needsLink) + ": the brick is not connected (" + runner_.state() +
                         "); nothing sent");
    }
    out = (this->*command.run)(c);
    break;
  }
  std::string notes;
  notes.swap(notes_);
  return notes + out;
}

std::string Console::poll() {
  std::string out;
  out.swap(notes_);
  if (!runner_.with([](link::Session& s) { return s.takeUnconfirmed(); }).empty()) {
    out +=
        "the brick did not know this console any more (it restarted, or another console talked to it): the "
        "command sent last may not have run; it is not sent again\n";
  }
  if (exploration_.active()) {
    out += pollHouse();
  } else {
    out += house_.pollRooms([this] { return dropGoalForNewRoom(); });
  }
  out += house_.pollUpload();
  out += goals_.poll();
  out += route_.poll();
  return out;
}

std::string Console::dropGoalForNewRoom() {
  goals_.clearBlocked();
  if (!goals_.active() && !route_.active()) return "";
  goals_.giveUp("unreachable: the brick went into another room");
  route_.cancel();
  return "goal dropped: the brick went into another room\n";
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

std::string Console::statusLine() const {
  const std::string state = runner_.state();
  return runner_.with([&](link::Session& s) { return statusLineText(state, s, goals_); });
}

std::string Console::leave(const ConsoleCommand&) {
  quit_ = true;
  return "";
}

std::string Console::explore(const ConsoleCommand&) {
  goals_.cancel();
  route_.cancel();
  runner_.with([](link::Session& s) { return s.explore(); });
  return "exploring\n";
}

double Console::clockS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string Console::exploreHouse(const ConsoleCommand&) {
  goals_.cancel();
  route_.cancel();
  return runner_.with([&](link::Session& s) { return exploration_.start(s, clockS()); });
}

std::string Console::pollHouse() {
  runner_.with([](link::Session& s) { return s.takeRoomChanges(); });  // the planner keeps the rooms
  std::string out = runner_.with([&](link::Session& s) { return exploration_.poll(s, clockS()); });
  if (!exploration_.done() && exploration_.stopped().empty()) return out;
  // The planner's house becomes the console's; the brick gets the room it stands in, in its frame.
  const int room = exploration_.roomOfRobot();
  if (room < 0) return out;
  network::HouseNetwork h = exploration_.planner().network();
  const network::RoomTransform toRoom = h.rooms()[static_cast<size_t>(room)].toHouse.inverse();
  const Pose b = exploration_.planner().belief();
  h.rooms()[0].labels["start"] = Cell{0, 0};  // where the robot was set down (room 0's origin)
  // The brick's cell size (its HelloReply), for save.
  house_.useHouse(h, exploration_.geometry().cellCm / 100.0, room);
  out += house_.enterHouseRoom();
  runner_.with([&](link::Session& s) { return s.setPose(Pose{toRoom.apply(b.cell), toRoom.apply(b.heading)}); });
  return out;
}

std::string Console::waitHouse(double seconds) {
  if (!exploration_.active() && !exploration_.done()) throw ConsoleError("wait house: explore house was not given");
  if (!waitFor([&] { return !exploration_.active(); }, seconds))
    throw ConsoleError("still mapping the house after " + std::to_string(static_cast<int>(seconds)) +
                       " s: " + exploration_.progress());
  if (!exploration_.stopped().empty())
    throw ConsoleError("house stopped: " + exploration_.stopped() + "; " + exploration_.progress());
  return "house mapped: " + exploration_.progress() + "\n";
}

std::string Console::stop(const ConsoleCommand&) {
  exploration_.cancel();
  goals_.cancel();
  route_.cancel();
  runner_.with([](link::Session& s) { return s.stop(); });
  return "stopping\n";
}

std::string Console::calibrate(const ConsoleCommand& c) {
  exploration_.cancel();
  goals_.cancel();
  route_.cancel();
  const std::string before = runner_.with([&](link::Session& s) {
    return s.brickCounters() ? turnErrorText(*s.brickCounters()) : std::string("not reported yet");
  });
  const uint16_t seq = runner_.with([](link::Session& s) { return s.calibrate(); });
  // The brick reports Exploring while it calibrates: from the second Status after the command was
  // acknowledged (the first may have left before it ran) until it rests again.
  uint64_t acked = 0;
  const auto statusAfterAck = [&] {
    return runner_.with([&](link::Session& s) {
      if (acked == 0 && s.acknowledged(seq)) acked = s.statusesReceived() + 1;
      return acked != 0 && s.statusesReceived() > acked;
    });
  };
  const auto mode = [&] { return runner_.with([](link::Session& s) { return s.status()->mode; }); };
  if (!waitFor(statusAfterAck, 10) || mode() != protocol::BrickMode::Exploring)
    throw ConsoleError("calibrate: the brick did not start calibrating (its image may have no sweep)");
  if (!waitFor([&] { return mode() != protocol::BrickMode::Exploring; }, c.seconds))
    throw ConsoleError("calibrate: still calibrating after " + std::to_string(static_cast<int>(c.seconds)) + " s");
  const uint64_t counters = runner_.with([](link::Session& s) { return s.countersReceived(); });
  (void)waitFor([&] { return runner_.with([&](link::Session& s) { return s.countersReceived() > counters; }); }, 5);
  return runner_.with([&](link::Session& s) {
    if (!s.brickCounters()) return std::string("calibrated (the brick has not reported its wheels yet)\n");
    return calibrationText(before, turnErrorText(*s.brickCounters()));
  });
}

std::string Console::route(const ConsoleCommand& c) {
  waitForUpload();
  return route_.start(c);
}

std::string Console::save(const ConsoleCommand& c) {
  if (c.name.size() > 5 && c.name.substr(c.name.size() - 5) == ".yaml") return house_.saveRoom(c.name);
  waitForUpload();
  return house_.saveHouse(c.name);
}

std::string Console::exportPicture(const ConsoleCommand& c) {
  const MapView v = goals_.view();
  if (v.bounds.empty()) throw ConsoleError("export: there is no map yet");
  std::string error;
  if (!writeMapPicture(v, c.name, error)) throw ConsoleError("export: " + error);
  return "exported " + c.name + "\n";
}

std::string Console::status(const ConsoleCommand&) {
  return runner_.with([&](link::Session& s) { return statusText(s, linkText_, goals_); });
}

std::string Console::battery(const ConsoleCommand&) {
  runner_.with([](link::Session& s) {
    s.requestBattery();
    s.requestLegoBattery();
    return 0;
  });
  const auto answered = [&] {
    return runner_.with(
        [](link::Session& s) { return s.batteryMillivolts().has_value() && s.legoBatteryMillivolts().has_value(); });
  };
  const bool got = waitFor(answered, 3.0);
  const auto mv = runner_.with([](link::Session& s) { return s.batteryMillivolts(); });
  const auto lego = runner_.with([](link::Session& s) { return s.legoBatteryMillivolts(); });
  if (!got && !mv && !lego) throw ConsoleError("battery: no answer from the brick within 3 s");
  return batteryText(mv, lego);
}

std::string Console::wait(const ConsoleCommand& c) {
  if (c.name == "house") return waitHouse(c.seconds);
  if (c.name == "explored") {
    const auto done = [&] {
      return runner_.with([](link::Session& s) { return s.status() && s.status()->mode == protocol::BrickMode::Done; });
    };
    if (!waitFor(done, c.seconds)) throw stillWaiting(c);
    return "exploring done\n";
  }
  if (!goals_.active() && !route_.active() && goals_.outcome().empty())
    throw ConsoleError("wait goal: no goal was given");
  const bool ok = waitFor([&] { return !goals_.active() && !route_.active(); }, c.seconds);
  if (ok && goals_.outcome() != "reached") throw ConsoleError("goal not reached: " + goals_.outcome());
  if (!ok) throw stillWaiting(c);
  return "done waiting: goal reached\n";
}

}  // namespace nxtmap::console
