// HouseExploration: `explore house` at the console. The PC's HousePlanner decides and the brick's
// HouseBrick carries its orders out over the link: the brick maps the room it stands in (confined);
// the planner takes the room's map (the PC's copy, complete once the brick reports the room's end)
// and its exits, picks the next unexplored exit, uploads the known house around the way there and
// sends the brick to the exit (GoTo), then through it into the next room (EnterRoom); until no exit
// is left. Every order is a reliable command, run once by the brick. Progress is reported as lines
// (rooms done, exits left, time). The link may drop and come back in between: the orders wait.
// Relocalisation by a standing scan and the start anchor are the simulator's only for now (the link
// carries no scan yet).
#pragma once
#include <chrono>
#include <optional>
#include <string>

#include "host/house/HousePlanner.hpp"
#include "host/link/LinkRunner.hpp"

namespace nxtmap::console {

class HouseExploration {
 public:
  explicit HouseExploration(link::LinkRunner& runner);

  // Starts mapping the house from the room the brick stands in. Returns what to print.
  std::string start();
  // Follows the brick; returns progress lines ("" when nothing new).
  std::string poll();
  bool active() const { return active_; }
  bool done() const { return done_; }
  const house::HousePlanner& planner() const { return *planner_; }
  house::HousePlanner& planner() { return *planner_; }
  // The room (index in the planner's network) the robot stands in, as believed.
  int roomOfRobot() const;
  std::string progress() const;

 private:
  enum class Wait { Nothing, Room, Goal, Cross };
  std::string send(const house::HouseOrder& o);
  std::optional<house::HouseReport> arrived();  // the report the brick gave for the current order
  house::HouseReport roomReport() const;

  link::LinkRunner& runner_;
  std::optional<house::HousePlanner> planner_;
  bool active_ = false, done_ = false;
  Wait wait_ = Wait::Nothing;
  uint16_t room_ = 0;  // the brick's id of the room being mapped (or entered)
  uint16_t goalId_ = 0, transferId_ = 0x4000;
  std::chrono::steady_clock::time_point started_{}, crossSince_{};
  int roomsMapped_ = 0;
};

}  // namespace nxtmap::console
