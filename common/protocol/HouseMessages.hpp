#pragma once
#include <cstddef>
#include <cstdint>

#include "common/explore/Explorer.hpp"
#include "common/grid/Cell.hpp"
#include "common/interpret/Doorway.hpp"
#include "common/protocol/Payload.hpp"
#include "common/sensing/RangeFilter.hpp"
#include "common/sensing/RangeReading.hpp"

// The payloads that map a house room by room: the PC chooses (Explore, GoTo, EnterRoom, Scan), the
// brick reports (RoomExits, NewRoom, Readings). Cells are room-map cells (int16 x, y) in the frame of the
// room named; Dir on the wire is a byte 0 N (+y), 1 E (+x), 2 S, 3 W. Codecs behave as in
// Messages.hpp: encoders write what they are given, decoders refuse anything out of range.
namespace nxtmap::protocol {

// A doorway (embedded in other messages, 7 bytes), as nxtmap::Doorway (common/interpret/Doorway.hpp):
// `width` cells from `first` along +x (alongX) or +y, `depth` cells across it (+y or +x).
// Every one of its cells is inside the coordinate range.
struct DoorwayMsg {
  Cell first{};
  uint8_t width = 1;  // 1..32
  uint8_t depth = 1;  // 1..8 (wall thickness)
  bool alongX = true;

  // The cell `along` cells along the gap and `across` cells across it from `first`.
  constexpr Cell cell(int along, int across) const {
    return alongX ? offset(first, along, across) : offset(first, across, along);
  }
  constexpr bool contains(Cell c) const {
    const int a = alongX ? c.x - first.x : c.y - first.y;
    const int b = alongX ? c.y - first.y : c.x - first.x;
    return a >= 0 && a < width && b >= 0 && b < depth;
  }
};
constexpr uint8_t kMaxDoorwayWidth = 32;

// The same doorway as the core's nxtmap::Doorway (common/interpret), both ways.
inline Doorway doorwayOf(const DoorwayMsg& m) {
  Doorway d;
  d.alongX = m.alongX;
  d.first = m.first;
  d.width = m.width;
  d.depth = m.depth;
  return d;
}
inline DoorwayMsg doorwayMessage(const Doorway& d) {
  DoorwayMsg m;
  m.alongX = d.alongX;
  m.first = d.first;
  m.width = static_cast<uint8_t>(d.width);
  m.depth = static_cast<uint8_t>(d.depth);
  return m;
}
constexpr uint8_t kMaxDoorwayDepth = 8;

// How a room is explored (a byte).
enum class ExploreStrategy : uint8_t { Propagation = 0, Frontier = 1 };

// ---- PC -> brick -------------------------------------------------------------------------

// Explore (2 bytes): start (or resume) exploring. Flags byte: bit 0 = confine, other bits 0.
struct ExploreMsg {
  ExploreStrategy strategy = ExploreStrategy::Frontier;
  bool confine = false;  // stay in the room the robot stands in (its doorways closed)
};
size_t encodeExplore(const ExploreMsg& m, Payload& out);
bool decodeExplore(const uint8_t* p, size_t n, ExploreMsg& out);

// GoTo (6 bytes): drive to `target` over the map the brick holds (its current room's frame).
struct GoToMsg {
  uint16_t goalId = 0;  // chosen by the PC, echoed in the brick's reports
  Cell target{};
};
size_t encodeGoTo(const GoToMsg& m, Payload& out);
bool decodeGoTo(const uint8_t* p, size_t n, GoToMsg& out);

// EnterRoom (15 bytes): cross `door` (in the current room's frame) heading `outward` from
// `inside`, then start room `roomId` beyond it with `strategy`, confined. `outward` crosses the
// doorway (North/South when alongX, else East/West) and one step from `inside` enters it.
struct EnterRoomMsg {
  uint16_t roomId = 0;
  ExploreStrategy strategy = ExploreStrategy::Frontier;
  DoorwayMsg door{};
  Dir outward = Dir::North;
  Cell inside{};  // the cell the robot stands on before crossing
};
size_t encodeEnterRoom(const EnterRoomMsg& m, Payload& out);
bool decodeEnterRoom(const uint8_t* p, size_t n, EnterRoomMsg& out);

// Scan (2 bytes): read the four sensors where the robot stands (a standing scan, for the PC to
// tell where the robot is when it seems lost); the brick's Readings echo `scanId` once it is done.
struct ScanMsg {
  uint16_t scanId = 0;  // chosen by the PC, 1..65535 (0: no scan)
};
size_t encodeScan(const ScanMsg& m, Payload& out);
bool decodeScan(const uint8_t* p, size_t n, ScanMsg& out);

// ---- brick -> PC -------------------------------------------------------------------------

// One exit of a room (12 bytes): as EnterRoomMsg's doorway, outward and inside.
struct RoomExitMsg {
  DoorwayMsg door{};
  Cell inside{};
  Dir outward = Dir::North;
};
constexpr uint8_t kMaxRoomExits = 8;

// RoomExits (4 + 12 per exit, at most 100 bytes): the exits the brick knows of the room it
// explores, and how its exploration stands. An absolute state: sent again and again.
struct RoomExitsMsg {
  uint16_t roomId = 0;
  ExplorerEnd end = ExplorerEnd::Running;
  uint8_t count = 0;  // 0..kMaxRoomExits
  RoomExitMsg exits[kMaxRoomExits] = {};
};
size_t encodeRoomExits(const RoomExitsMsg& m, Payload& out);
bool decodeRoomExits(const uint8_t* p, size_t n, RoomExitsMsg& out);

// NewRoom (13 bytes): the robot went through an exit into another room; a new map epoch starts
// with it. The new room's frame in the room it came from: its (0, 0) is `origin` and its +y is
// `heading`.
struct NewRoomMsg {
  uint16_t roomId = 0;  // counts rooms entered since power-on
  Cell entry{};         // entry cell in the new room's frame
  uint16_t fromRoom = 0;
  Cell origin{};
  Dir heading = Dir::North;
};
size_t encodeNewRoom(const NewRoomMsg& m, Payload& out);
bool decodeNewRoom(const uint8_t* p, size_t n, NewRoomMsg& out);

// One filtered reading (embedded, 2 bytes): cm (0..255: a sonar byte or the mean of some), then
// status (RangeStatus 0..4) in the low nibble and samples (0..RangeFilter::kMaxSamples; 0: never
// read) in the high nibble.
constexpr int16_t kMaxReadingCm = 255;

// Readings (15 bytes): the last standing scan, sent again and again while the brick maps a house (an
// absolute state, like RoomExits): `scanId` of the Scan command it answered (0: none yet), the pose it
// was taken at (the brick's current room frame) and its readings Front, Right, Back, Left.
struct ReadingsMsg {
  uint16_t scanId = 0;
  Pose scanPose{};
  RangeReading scan[kSensorCount] = {};
};
size_t encodeReadings(const ReadingsMsg& m, Payload& out);
bool decodeReadings(const uint8_t* p, size_t n, ReadingsMsg& out);

}  // namespace nxtmap::protocol
