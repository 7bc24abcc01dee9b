#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"
#include "common/grid/RoomGrid.hpp"
#include "common/interpret/Doorway.hpp"

namespace nxtmap {

// Sides of a room, in the map's frame (+y = North).
enum class Side : uint8_t { North = 0, East = 1, South = 2, West = 3 };

// An opening in a wall: a run of free cells on the wall line.
struct Exit {
  Side side = Side::North;
  Cell first{};       // first cell of the run (lowest x on N/S walls, lowest y on E/W walls)
  int16_t width = 0;  // cells
  Cell middle() const;
};

// Room size limits in cells (interior, walls excluded).
struct RoomLimits {
  int16_t minSide = 3;    // below: not a room
  int16_t maxSide = 120;  // above: several rooms
};

enum class RoomClass : uint8_t { Room, TooSmall, TooLarge, Unknown };

// Grid interpretation (3.5.5): the walls as the lines with the most occupied cells that have
// unknown cells beyond them (the robot cannot read through a wall), the room size from the
// walls, and the exits, any number per side: runs of free cells on the wall lines, plus the
// doorways inside the walls' box (rooms that are not rectangles: an L-shaped room's inner wall,
// a wall of a corridor; see findDoorways), given the side of the nearer wall parallel to them.
// A room larger than the maximum is cut into partsX x partsY rooms of at most maxSide.
struct RoomInterpretation {
  static constexpr uint8_t kMaxExits = 16;
  bool valid = false;         // false when the map holds no walls at all
  int16_t wallLine[4] = {};   // y of the N and S walls, x of the E and W walls
  int16_t wallCells[4] = {};  // occupied cells found on each wall line
  Exit exits[kMaxExits];
  uint8_t exitCount = 0;
  bool moreExits = false;  // more than kMaxExits openings
  RoomClass roomClass = RoomClass::Unknown;
  uint8_t partsX = 0, partsY = 0;  // rooms the area makes along x and y (1 x 1 for a Room)
  int32_t freeCells = 0;           // free cells inside the walls (the floor area seen)

  int16_t interiorWidth() const { return static_cast<int16_t>(wallLine[1] - wallLine[3] - 1); }
  int16_t interiorHeight() const { return static_cast<int16_t>(wallLine[0] - wallLine[2] - 1); }
};

RoomInterpretation interpretRoom(const RoomGrid& grid, const RoomLimits& limits = RoomLimits{},
                                 const DoorwayLimits& doorways = DoorwayLimits{});

}  // namespace nxtmap
