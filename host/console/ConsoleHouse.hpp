// ConsoleHouse: the console's house session (host/network): every room seen or loaded, each in its own
// frame, with gateways and labels. The current room's map is the live map (the brick's, in the room's
// frame); the others are kept as they were last seen. When the brick reports a new room, the room it
// left is kept and a new one starts, joined by a one-cell gateway where the robot crossed (the brick
// starts the new room's frame at the robot's pose, so the transform is known) when the robot's last
// pose in the old room is known; otherwise the new room is "not connected". A room's map goes to the
// brick as a MapChunk upload, which counts as taken once the brick echoes it (a new map epoch).
#pragma once
#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "host/link/LinkRunner.hpp"
#include "host/network/HouseNetwork.hpp"

namespace nxtmap::console {

class ConsoleHouse {
 public:
  // One room, "room0", at the house origin.
  explicit ConsoleHouse(link::LinkRunner& runner);

  // Takes a loaded house; the brick stands in room `room`. Throws ConsoleError for a room that is not
  // in the house.
  void useHouse(network::HouseNetwork house, double resolutionM, int room);
  // Uploads the current room's map to the brick (call when connected). Returns what to print.
  std::string enterHouseRoom();

  const network::HouseNetwork& house() const { return house_; }
  int currentRoom() const { return current_; }
  // The house with the current room's live map in place (what save writes and routes use).
  network::HouseNetwork snapshot() const;
  // The current room's labels (room-frame cells).
  std::map<std::string, Cell>& labels() { return house_.rooms()[static_cast<size_t>(current_)].labels; }
  // Whether room `room`'s place in the house is known.
  bool placed(int room) const { return placed_[static_cast<size_t>(room)]; }
  // An upload the brick has not echoed yet; the live map is the current room's when liveValid().
  bool uploadPending() const { return echo_.pending; }
  bool liveValid() const { return liveValid_; }

  // Keeps the current room's map of `snap` (a snapshot()) as the room's stored map.
  void keepCurrentMap(const network::HouseNetwork& snap);
  // The robot moves to room `to` through a gateway: keeps the room it leaves, uploads `to`'s map and
  // makes `to` current. Throws ConsoleError (then the current room stays) when the map cannot go.
  void switchTo(int to);

  // Room changes the brick reported: `onNewRoom` runs for each (it drops a goal and says so) before the
  // new room starts. Returns the lines to print.
  std::string pollRooms(const std::function<std::string()>& onNewRoom);
  // Watches an upload's echo. Returns "" (nothing to print).
  std::string pollUpload();

  // `rooms`: one line per room (the current one marked), exits and labels.
  std::string roomsText() const;
  // `save DIR` (the house) and `save FILE.yaml` (the current room as a ROS map). Throw ConsoleError.
  std::string saveHouse(const std::string& dir) const;
  std::string saveRoom(const std::string& file);

 private:
  // Waiting for the brick to echo an uploaded room map (its new epoch with the cells).
  struct UploadEcho {
    bool pending = false;
    bool hadEpoch = false;
    uint16_t epochBefore = 0;
    size_t cells = 0;  // known cells uploaded
    std::chrono::steady_clock::time_point since{};
  };
  // The room map of the live map over the union of its known box and the stored room's box.
  network::RoomMap liveRoomMap(const link::Session& s) const;
  void uploadRoom(int room);
  void keepLeftRoom(const link::MirrorMap& left);
  std::string startNewRoom(const link::RoomChange& c);
  std::string roomLine(const network::HouseNetwork& h, size_t i, const std::optional<Pose>& pose) const;

  link::LinkRunner& runner_;
  network::HouseNetwork house_;  // every room; labels per room (room-frame cells)
  std::vector<bool> placed_;     // per room: whether its place in the house is known
  double resolutionM_ = 0.10;    // metres a cell, for saving
  int current_ = 0;              // the room the brick is in (its map frame)
  bool liveValid_ = true;        // the live map is the current room's (not while an upload echoes)
  UploadEcho echo_;
  uint16_t nextTransferId_ = 1;
};

}  // namespace nxtmap::console
