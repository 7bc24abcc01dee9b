// RouteDriver: a route to another room (network::planHouseRoute over the house's snapshot) driven leg
// by leg: each leg is a goal in its room (GoalDriver); at each gateway the next room's map is uploaded
// to the brick with the robot's pose in that room's frame (MapChunk + SetPose), and the next leg starts
// once the brick holds both (given up after kSwitchGiveUpS).
#pragma once
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "host/console/ConsoleCommand.hpp"
#include "host/console/ConsoleHouse.hpp"
#include "host/console/GoalDriver.hpp"
#include "host/network/HouseRoute.hpp"

namespace nxtmap::console {

class RouteDriver {
 public:
  static constexpr double kSwitchGiveUpS = 30.0;  // a room switch the brick does not confirm is given up
  RouteDriver(link::LinkRunner& runner, ConsoleHouse& house, GoalDriver& goals)
      : runner_(runner), house_(house), goals_(goals) {}

  // `route ROOM C R` / `route near LABEL`: plans and starts the first leg. Throws ConsoleError (nothing
  // sent) for a route that cannot be driven. Returns what to print.
  std::string start(const ConsoleCommand& c);
  // Follows the legs and the room switches; call often. Returns a line to print or "".
  std::string poll();
  bool active() const { return active_; }
  void cancel() { active_ = false; }

 private:
  network::RoomPoint target(const ConsoleCommand& c, const network::HouseNetwork& h, const std::string& what) const;
  void checkRooms(const network::HouseRoute& r, const network::HouseNetwork& h, const std::string& what) const;
  std::string switchRoom();
  std::string pollSwitch();

  link::LinkRunner& runner_;
  ConsoleHouse& house_;
  GoalDriver& goals_;
  // legs_[leg_] is being driven (or, while switching, is about to start once the brick holds its
  // room's map and the pose sent with it).
  bool active_ = false;
  std::vector<network::HouseLeg> legs_;
  size_t leg_ = 0;
  bool switching_ = false;
  Pose arrival_{};        // the robot's pose in the new room (sent with SetPose)
  uint16_t poseSeq_ = 0;  // the SetPose command
  std::chrono::steady_clock::time_point since_{};
};

}  // namespace nxtmap::console
