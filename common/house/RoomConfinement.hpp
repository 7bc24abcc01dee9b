// RoomConfinement: keeps an explorer in the room it started in (method section 5: one room map
// per room). After every event it looks for doorways near the robot in the map (findDoorways). A
// doorway that separates the room's start (the origin of the room's frame) from what lies beyond
// it, with the robot on the start's side, becomes an exit: its cells are held as walls in the
// explorer's map ("virtual doors") so the explorer maps this room only. The entrance is closed the
// same way from the start, with guard cells beyond each end of its line. A doorway straight ahead is
// only recognised from inside it (the side sensors see its jambs there): the robot's side is then
// the last cell it stood on outside every doorway, and the exit is held shut one line further out,
// beyond the robot. When the explorer is done, finish() opens the doors again (free) and keeps the
// exits whose inside cell the start reaches. The sonar sees through doorways, and on a grid of fixed
// capacity what it saw beyond them can take the room its own far side needs: while the grid is full
// along an axis and the room has exits, the cells beyond them are forgotten and the window shrinks.
//
// Runs on the brick: fixed capacities, no heap; the reach flood works in caller-owned bits.
#pragma once
#include <cstdint>

#include "common/grid/CellSet.hpp"
#include "common/grid/MapLayers.hpp"
#include "common/house/RoomExit.hpp"
#include "common/interpret/Doorway.hpp"
#include "common/motion/DriveAction.hpp"
#include "common/explore/Pose.hpp"

namespace nxtmap {

class RoomConfinement final : public CellSet {
 public:
  static constexpr uint8_t kMaxExits = 8;        // exits kept per room (more: counted in overflow())
  static constexpr uint8_t kMaxCandidates = 16;  // doorways seen that are not (yet) exits
  static constexpr uint8_t kMaxFound = 32;       // doorways one look may find
  static constexpr int16_t kGuardCells = 2;      // closed beyond each end of the entrance's line
  static constexpr int kRecheckSteps = 25;       // events between two evaluations of the candidates
  static constexpr int kSureEvidence = 1;        // |evidence| a doorway's cells need
  static constexpr int16_t kOpenBeside = 2;      // free cells beside each jamb, seen from inside a gap

  // reachBits: packedBytes(width, height, 1) bytes for a map of that capacity, owned by the caller.
  // lookCells: how far around the robot to look, beyond the doorway's width (the sonar's reach).
  RoomConfinement(uint8_t* reachBits, int16_t width, int16_t height, const DoorwayLimits& limits, int16_t lookCells);

  // A new room: forgets everything; `entrance` (room frame) is closed with its guards (nullptr: none).
  void begin(const Doorway* entrance);
  // Marks every shut cell (closed doors and guards) blocked in the map.
  void hold(MapLayers& map) const;
  // A drive the pilot asks for from pose `p` would enter a shut cell.
  bool drivesIntoShut(const Pose& p, const DriveAction& a) const;
  // After an event: looks for doorways around `robot` and closes the new exits (then holds them).
  void look(MapLayers& map, Cell robot);
  // The explorer is done: the doors open again (free), the cells the start reaches without crossing
  // a door are flooded (reached()), and only the exits with their inside cell reached stay.
  void finish(MapLayers& map);

  bool contains(Cell c) const override;  // a shut cell (held blocked: a closed door or a guard)
  bool reached(Cell c) const;            // after finish()
  bool hasEntrance() const { return hasEntrance_; }
  const Doorway& entrance() const { return entrance_; }
  uint8_t exitCount() const { return exitCount_; }
  const RoomExit& exit(uint8_t i) const { return exits_[i]; }
  uint8_t ignored() const { return candidateCount_; }  // doorways seen that never became exits
  uint16_t overflow() const { return overflow_; }      // exits or candidates dropped for capacity

 private:
  bool closed(Cell c) const;  // entrance or exit cells, or an exit's shut line (not the guards)
  bool inCandidate(Cell c) const;
  // Where the robot is for deciding sides: its cell, or when that lies in a doorway (closed or a
  // candidate) the last cell it left outside them.
  Cell robotSide(Cell robot) const;
  bool wellSeen(const MapLayers& map, const Doorway& d) const;
  bool isExit(const Doorway& d) const;  // overlaps an exit's door (held shut beyond: still seen free)
  void remember(const Doorway& d, bool& changed);
  void lookWhereStanding(MapLayers& map, Cell robot, bool& changed);
  bool openBeforeJambs(const MapLayers& map, const Doorway& d) const;
  void evaluate(MapLayers& map, Cell robot);
  // The grid is full along an axis and the room has exits: what was seen through them (not this room's) is
  // forgotten and the window shrunk, so that the room's own far side still fits.
  void forgetBeyondExits(MapLayers& map);
  // Floods from the start over free cells of the map's window, never into a closed door (entrance or exit
  // cells, an exit's shut line) nor, as `stop` says, into any shut cell (the entrance's guards too:
  // kShut) or a candidate's cells (kCandidates); the result is in the reach bits (reached()).
  enum FloodStop : uint8_t { kDoors = 0, kShut = 1, kCandidates = 2 };
  void flood(const RoomGrid& grid, uint8_t stop);
  bool seen(Cell c) const;
  void see(Cell c);

  uint8_t* reachBits_;
  int16_t width_, height_;
  DoorwayLimits limits_;
  int16_t lookCells_;
  Bounds reachBox_{};
  bool hasEntrance_ = false;
  Doorway entrance_{};
  Doorway guards_[2] = {};  // the cells beside the entrance along its line, kGuardCells deep
  RoomExit exits_[kMaxExits] = {};
  Doorway shut_[kMaxExits] = {};  // the cells held blocked for exit i: its door, or the line beyond it
  Cell here_{};                   // the robot's cell at the last look (room frame)
  Cell outside_{};                // the last cell it left that lies outside every doorway
  uint8_t exitCount_ = 0;
  Doorway candidates_[kMaxCandidates] = {};
  uint8_t candidateCount_ = 0;
  Doorway found_[kMaxFound] = {};
  int sinceCheck_ = 0;
  uint16_t overflow_ = 0;
};

}  // namespace nxtmap
