// Console: carries out console commands against a running link: the map the PC holds (shown
// with the robot), goals planned on it with host/plan and sent as paths (in pieces of at most
// kSegmentCells cells, replanned when the brick reports "blocked"), labels, save and export.
// A bad goal (outside the map, an obstacle, unexplored, unreachable) is refused with one clear
// message and nothing is sent.
//
// The console keeps a house (host/network): every room seen or loaded, each in its own frame,
// with gateways and labels. The current room's map is the live map (the brick's, in the room's
// frame); the others are kept as they were last seen. When the brick reports a new room, the room
// it left is kept and a new one starts, joined by a one-cell gateway where the robot crossed (the
// brick starts the new room's frame at the robot's pose, so the transform is known) when the
// robot's last pose in the old room is known; otherwise the new room is "not connected". A route
// to another room is planned across rooms (network::planHouseRoute) and driven leg by leg: at each
// gateway the next room's map is uploaded to the brick with the robot's pose in that room's frame
// (MapChunk + SetPose), then the next leg is sent.
#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "host/console/ConsoleCommand.hpp"
#include "host/link/LinkRunner.hpp"
#include "host/mapio/OccupancyMap.hpp"
#include "host/network/HouseRoute.hpp"
#include "host/plan/Traversability.hpp"

namespace nxtmap::console {

// The PC's map as an OccupancyMap over the known cells' bounding box: column = x - minX,
// row = maxY - y (row grows down, +y is the robot's initial forward).
struct MapView {
  mapio::OccupancyMap map;
  Bounds bounds;
  std::optional<plan::MapCell> robot;  // when the pose is known and inside
  Dir heading = Dir::North;
  bool toMap(Cell c, int& col, int& row) const;
  Cell toCell(int col, int row) const;
};
MapView viewOf(const link::Session& session, const std::set<std::pair<int, int>>& blocked = {});

class Console {
 public:
  static constexpr size_t kSegmentCells = 32;
  explicit Console(link::LinkRunner& runner, std::string linkText);

  // Carries out one command; returns what to print. Throws ConsoleError for a refused command
  // (nothing was sent). Quit returns "" and sets quit().
  std::string execute(const ConsoleCommand& c);
  // Follows the current goal (next segment, replanning); call often. Returns a line to print or "".
  std::string poll();
  bool quit() const { return quit_; }
  std::string renderMap() const;
  std::string statusLine() const;
  // Called about every 20 ms while a command waits (wait explored/goal), e.g. to redraw a live map.
  void onWaiting(std::function<void()> f) { waiting_ = std::move(f); }

  // Takes a loaded house; the brick stands in room `room` (its pose is read in that room's frame):
  // that room's map is uploaded once the link is up (enterHouseRoom). Throws ConsoleError for a
  // room that is not in the house or does not fit the brick.
  void useHouse(network::HouseNetwork house, double resolutionM, int room);
  // Uploads the current room's map to the brick (call when connected). Returns what to print.
  std::string enterHouseRoom();
  const network::HouseNetwork& house() const { return house_; }
  int currentRoom() const { return current_; }
  // The house with the current room's live map in place (what save writes and routes use).
  network::HouseNetwork snapshot() const;

 private:
  struct Goal {
    Cell target{};
    uint16_t pathId = 0;
    std::vector<Cell> path;  // whole remaining route
    size_t sentUpTo = 0;     // index in path of the current segment's last cell
    int replans = 0;
    bool active = false;
    std::string outcome;  // "reached", "unreachable: ..."
  };
  // A route across rooms being driven: legs[leg] is being driven (or, while switching, is about
  // to start once the brick holds its room's map and the pose sent with it).
  struct RouteDrive {
    bool active = false;
    std::vector<network::HouseLeg> legs;
    size_t leg = 0;
    bool switching = false;
    Pose arrival{};        // the robot's pose in the new room (sent with SetPose)
    uint16_t poseSeq = 0;  // the SetPose command
    std::chrono::steady_clock::time_point since{};
  };
  // Waiting for the brick to echo an uploaded room map (its new epoch with the cells).
  struct UploadEcho {
    bool pending = false;
    bool hadEpoch = false;
    uint16_t epochBefore = 0;
    size_t cells = 0;  // known cells uploaded
    std::chrono::steady_clock::time_point since{};
  };
  std::string startGoal(Cell target, const std::string& what);
  std::string startPath(const std::vector<Cell>& path, const std::string& what);
  std::vector<Cell> planTo(Cell target, std::string& why) const;
  void sendSegment();
  std::string executeCommand(const ConsoleCommand& c);
  std::string pollGoal();
  std::string startRoute(const ConsoleCommand& c);
  std::string switchRoom();
  std::string pollRoute();
  std::string pollRooms();
  std::string pollUpload();
  void uploadRoom(int room);
  std::string roomsText() const;
  std::string saveHouse(const std::string& dir);
  std::string saveRoom(const std::string& file);
  // The room map of the live map over the union of its known box and the stored room's box.
  network::RoomMap liveRoomMap(const link::Session& s) const;
  std::map<std::string, Cell>& labels() { return house_.rooms()[static_cast<size_t>(current_)].labels; }
  bool waitFor(const std::function<bool()>& done, double seconds);
  std::function<void()> waiting_;

  link::LinkRunner& runner_;
  std::string linkText_;
  std::set<std::pair<int, int>> blocked_;  // cells the brick reported blocked (current room's frame)
  network::HouseNetwork house_;            // every room; labels per room (room-frame cells)
  std::vector<bool> placed_;               // per room: whether its place in the house is known
  double resolutionM_ = 0.10;
  int current_ = 0;        // the room the brick is in (its map frame)
  bool liveValid_ = true;  // the live map is the current room's (not while an upload echoes)
  UploadEcho echo_;
  RouteDrive route_;
  uint16_t nextTransferId_ = 1;
  Goal goal_;
  std::string notes_;  // lines poll() produced while a command waited (printed with its answer)
  uint16_t nextPathId_ = 1;
  bool quit_ = false;
};

}  // namespace nxtmap::console
