// Console: carries out console commands against a running link. Each command is one row of a command
// table (Console.cpp: the command, whether it needs the link, its handler); the handlers are short and
// lean on collaborators:
//   GoalDriver    goals planned on the PC's map (MapView, host/plan) and sent as paths in pieces,
//                 replanned when the brick reports "blocked";
//   ConsoleHouse  the house session: rooms seen or loaded, room changes, uploads, labels, save;
//   RouteDriver   routes across rooms driven leg by leg through the gateways;
//   HouseExploration  `explore house`: the PC's house planner driving the brick room by room;
//   MapView       the map shown by `map` and written by `export` (host/report).
// A bad goal (outside the map, an obstacle, unexplored, unreachable) is refused with one clear message
// and nothing is sent.
#pragma once
#include <functional>
#include <string>

#include "host/console/ConsoleCommand.hpp"
#include "host/console/ConsoleHouse.hpp"
#include "host/console/GoalDriver.hpp"
#include "host/console/HouseExploration.hpp"
#include "host/console/MapView.hpp"
#include "host/console/RouteDriver.hpp"
#include "host/link/LinkRunner.hpp"

namespace nxtmap::console {

class Console {
 public:
  static constexpr size_t kSegmentCells = GoalDriver::kSegmentCells;
  explicit Console(link::LinkRunner& runner, std::string linkText);

  // Carries out one command; returns what to print. Throws ConsoleError for a refused command
  // (nothing was sent). Quit returns "" and sets quit().
  std::string execute(const ConsoleCommand& c);
  // Follows the current goal (next segment, replanning); call often. Returns a line to print or "".
  std::string poll();
  bool quit() const { return quit_; }
  std::string renderMap() const { return mapText(goals_.view()); }
  std::string statusLine() const;
  // Called about every 20 ms while a command waits (wait explored/goal), e.g. to redraw a live map.
  void onWaiting(std::function<void()> f) { waiting_ = std::move(f); }

  // Takes a loaded house; the brick stands in room `room` (its pose is read in that room's frame):
  // that room's map is uploaded once the link is up (enterHouseRoom). Throws ConsoleError for a
  // room that is not in the house.
  void useHouse(network::HouseNetwork house, double resolutionM, int room) {
    house_.useHouse(std::move(house), resolutionM, room);
  }
  // Uploads the current room's map to the brick (call when connected). Returns what to print.
  std::string enterHouseRoom() { return house_.enterHouseRoom(); }
  const network::HouseNetwork& house() const { return house_.house(); }
  int currentRoom() const { return house_.currentRoom(); }
  // The house with the current room's live map in place (what save writes and routes use).
  network::HouseNetwork snapshot() const { return house_.snapshot(); }

 private:
  using Handler = std::string (Console::*)(const ConsoleCommand&);
  // A row of the command table: `needsLink` names the command when it needs the brick connected.
  struct Command {
    ConsoleCommand::Kind kind;
    const char* needsLink;
    Handler run;
  };
  static const Command kCommands[];

  // The handlers, one per command.
  std::string empty(const ConsoleCommand&) { return ""; }
  std::string help(const ConsoleCommand&) { return consoleHelp(); }
  std::string leave(const ConsoleCommand&);
  std::string explore(const ConsoleCommand&);
  std::string exploreHouse(const ConsoleCommand&);
  std::string stop(const ConsoleCommand&);
  // Sends Calibrate and waits (ConsoleCommand::seconds) until the brick rests again, then says what it measured.
  std::string calibrate(const ConsoleCommand& c);
  std::string gotoCell(const ConsoleCommand& c);
  std::string gotoNear(const ConsoleCommand& c);
  std::string label(const ConsoleCommand& c);
  std::string rooms(const ConsoleCommand&) { return house_.roomsText(); }
  std::string route(const ConsoleCommand& c);
  std::string save(const ConsoleCommand& c);
  std::string exportPicture(const ConsoleCommand& c);
  std::string status(const ConsoleCommand&);
  std::string battery(const ConsoleCommand&);
  std::string map(const ConsoleCommand&) { return renderMap(); }
  std::string wait(const ConsoleCommand& c);

  std::string startGoal(Cell target, const std::string& what);
  std::string dropGoalForNewRoom();
  std::string pollHouse();  // the house exploration; once it is done, its house becomes the console's
  std::string waitHouse(double seconds);
  static double clockS();  // seconds of a steady clock
  bool waitFor(const std::function<bool()>& done, double seconds);
  void waitForUpload() {
    if (house_.uploadPending()) waitFor([&] { return !house_.uploadPending(); }, 5.0);
  }

  link::LinkRunner& runner_;
  std::string linkText_;
  GoalDriver goals_;
  ConsoleHouse house_;
  RouteDriver route_;
  HouseExploration exploration_;
  std::function<void()> waiting_;
  std::string notes_;  // lines poll() produced while a command waited (printed with its answer)
  bool quit_ = false;
};

}  // namespace nxtmap::console
