// HouseExploration: `explore house` at the console. The PC's HousePlanner decides and the brick's
// HouseBrick carries its orders out over the link: the brick maps the room it stands in (confined);
// the planner takes the room's map (the PC's copy, complete once the brick reports the room's end)
// and its exits, picks the next unexplored exit, uploads the known house around the way there and
// sends the brick to the exit (GoTo), then through it into the next room (EnterRoom); until no exit
// is left. A robot that seems lost is told to scan standing (Scan; the four readings come back in
// Readings), as in `sim-house`. Every order is a reliable command, run once by the brick. Progress is reported as
// lines (rooms done, exits left, time). The link may drop and come back in between: the orders wait.
// Works on the PC's Session directly (the console calls it under the link runner's lock); times are
// seconds of the caller's clock.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "host/house/HousePlanner.hpp"
#include "host/link/Session.hpp"

namespace nxtmap::console {

class HouseExploration {
 public:
  // Starts mapping the house from the room the brick stands in, planning with the brick's grid
  // and range geometry as its HelloReply gave them (ConsoleError before the brick answered).
  // Returns what to print.
  std::string start(link::Session& s, double nowS);
  // Follows the brick; returns progress lines ("" when nothing new).
  std::string poll(link::Session& s, double nowS);
  // Gives up (the console's stop): nothing more is sent.
  void cancel() { active_ = false; }
  bool active() const { return active_; }
  bool done() const { return done_; }
  // Why the house stopped before it was done ("" while it runs, when done or cancelled): the brick
  // stopped its motors, or its order was cut short on the brick.
  const std::string& stopped() const { return stopped_; }
  const house::HousePlanner& planner() const { return *planner_; }
  house::HousePlanner& planner() { return *planner_; }
  // The room (index in the planner's network) the robot stands in, as believed.
  int roomOfRobot() const;
  std::string progress() const;
  int roomsMapped() const { return roomsMapped_; }
  // The cells the brick's statuses put it in while it maps the room it is mapping now (that room's frame, each
  // once in a row): with the room's map, they tell the planner which part of the map is the room.
  const std::vector<Cell>& stoodInRoom() const { return stood_; }
  // How the brick's sensors read (cell size, trusted range, mount), as of the last start().
  const RangeGeometry& geometry() const { return geometry_; }

 private:
  enum class Wait { Nothing, Room, Goal, Cross, Scan };
  std::string send(link::Session& s, const house::HouseOrder& o);
  std::string sendOrder(link::Session& s, const house::HouseOrder& o);
  void sendTravel(link::Session& s, const house::HouseOrder& o);
  void sendCross(link::Session& s, const house::HouseOrder& o);
  // The report the brick gave for the current order, once it is complete.
  std::optional<house::HouseReport> arrived(link::Session& s);
  // Why the brick can no longer carry the current order out ("" while it can).
  std::string brickGaveUp(const link::Session& s);
  bool standingStill(const link::Session& s);
  std::optional<house::HouseReport> crossBlocked(link::Session& s);
  std::optional<house::HouseReport> roomDone(link::Session& s) const;
  std::optional<house::HouseReport> goalDone(link::Session& s) const;
  std::optional<house::HouseReport> scanDone(link::Session& s) const;
  house::HouseReport roomReport(link::Session& s) const;
  void noteWhereItStands(const link::Session& s);

  RangeGeometry geometry_;  // the brick's, from its HelloReply at start()
  std::optional<house::HousePlanner> planner_;
  bool active_ = false, done_ = false;
  std::string stopped_;
  Wait wait_ = Wait::Nothing;
  uint16_t room_ = 0;  // the brick's id of the room being mapped (or entered)
  uint16_t goalId_ = 0, transferId_ = 0x4000;
  uint16_t scanId_ = 0;         // the last Scan's id (1..65535)
  uint16_t enterSeq_ = 0;       // the EnterRoom command's sequence number
  uint64_t statusesAtAck_ = 0;  // statuses received when it was acknowledged (0: not yet)
  double startedS_ = 0, crossSinceS_ = 0, nowS_ = 0;
  uint64_t stillFrom_ = 0;  // statuses received when the brick was first seen still (0: moving)
  double stillSinceS_ = 0;
  int roomsMapped_ = 0;
  std::vector<Cell> stood_;  // the cells the brick's statuses put it in while it maps room_ (HouseReport::stood)
};

}  // namespace nxtmap::console
