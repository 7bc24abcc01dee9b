#pragma once
#include <cstdint>

#include "common/protocol/Messages.hpp"

namespace nxtmap::protocol {

// A command from the PC for the firmware to carry out. BrickLink hands each one over exactly
// once, in the order the PC sent them.
enum class CommandKind : uint8_t {
  Explore,     // start or resume exploring (`explore`: how; confined: a room of a house)
  Stop,        // stop moving, stay where you are
  FollowPath,  // drive along `path` (cell 0 = where the robot stands); report PathProgress
  MapChunk,    // part of a whole map from the PC (`chunk`); chunk 0 of a transfer: clear first
  SetPose,     // the robot stands at `pose` on the map it holds (e.g. a room just uploaded); stop first
  GoTo,        // drive to `goTo.target` over the map held; report PathProgress with pathId = goalId
  EnterRoom,   // cross `enterRoom.door` and map the room beyond it, confined
  Scan,        // read the four sensors where the robot stands; report Readings with scanId = `scan.scanId`
  Calibrate,   // measure the turns' error where the robot stands (sweep, whole turns, sweep), keep it, rest
};

struct Command {
  CommandKind kind = CommandKind::Stop;
  uint16_t seq = 0;  // the PC's sequence number (for logs)
  // What the command carries: the member `kind` names (one at a time, so the brick's queue of
  // commands holds the largest of them only). BrickLink starts the member's lifetime.
  union {
    PathMsg path;            // FollowPath
    MapChunkMsg chunk;       // MapChunk
    Pose pose;               // SetPose
    ExploreMsg explore;      // Explore
    GoToMsg goTo;            // GoTo
    EnterRoomMsg enterRoom;  // EnterRoom
    ScanMsg scan;            // Scan
  };
  Command() : path() {}
};

}  // namespace nxtmap::protocol
