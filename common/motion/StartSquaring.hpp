#pragma once
#include <cstdint>

#include "common/motion/DriveAction.hpp"
#include "common/motion/DriveEvent.hpp"
#include "common/sensing/WallDirection.hpp"

namespace nxtmap {

// StartSquaring: a robot set down a few degrees off square turns square to the room's walls before it
// maps. Events in, actions out, as the pilot's: it turns to -sweep, then reads its four sensors at every
// step up to +sweep (the headings the wheels report: DriveEvent::rotatedBy, or as commanded), asks
// WallDirection where the walls' normals are, and turns onto the nearest one to the heading it was set down
// on, so the map's north stays within 45 degrees of the robot's start heading. With no wall found it turns
// back to where it started. Memory: one WallDirection (about 0.5 KiB).
class StartSquaring {
 public:
  // sweepMrad: the sweep's half-width (the default +-90 deg sees a wall at any angle whole);
  // stepMrad: between headings (5 deg: a dip is 60-75 deg wide). At most WallDirection::kMaxSteps headings.
  // coneHalfMrad: the sonar's widest beam half-angle (WallDirection's dip widths).
  explicit StartSquaring(int32_t sweepMrad = 1571, int32_t stepMrad = 87, int16_t approachFromCm = 70,
                         int32_t coneHalfMrad = WallDirection::kNxtConeMrad);

  // approachesLeft: how many more times the pilot would drive towards an echo (approachEcho()) if this sweep saw
  // no straight wall; with none left, or no such echo, the sweep takes the widest wall dip alone
  // (WallDirection::widestWall) rather than none. Negative: never (a calibration's sweeps).
  DriveAction begin(int approachesLeft = -1);
  // The answer to the previous action; returns the next. DriveAction::done() once square.
  DriveAction step(const DriveEvent& e);
  bool finished() const { return phase_ == Phase::Done; }

  const WallDirectionEstimate& result() const { return result_; }
  // The robot's heading minus the walls' axis it turned onto, as the encoders tell it (mrad, + clockwise).
  int32_t residualMrad() const { return headingMrad_ - targetMrad_; }
  // The echo of the sweep to drive towards when it found no wall, at least approachFromCm away: its direction from
  // the sweep's zero (mrad, + clockwise, -pi..pi) and range (cm). The nearest at first (in most rooms a wall is
  // near); once an approach found no wall there (avoid()), the farthest up to kFarthestCm: the nearer echoes are
  // things standing in a large room, and what bounds a room is its walls. (Farther echoes come off walls at a
  // slant, towards a corner: in an empty 4.4 m room an approach there ended beside one wall, 7 degrees off.)
  static constexpr int16_t kFarthestCm = 230;
  struct Echo {
    bool seen = false;
    int32_t mrad = 0;
    int16_t cm = 0;
  };
  const Echo& approachEcho() const { return target_; }
  // The whole sweep was read and no reading had an echo at all (nor one too near): nothing stands within the
  // sensors' reach in any direction, the middle of a hall (an approach may drive blind). A stalled sweep (the
  // body met something) heard something.
  bool heardNothing() const { return !heard_ && !stalled_; }
  // Echoes within a sixth of a turn of `mrad` (from the sweep's zero) are not taken from now on: the way an
  // approach went (kept across begin()), and from now on the farthest echo is taken.
  void avoid(int32_t mrad) {
    avoiding_ = true;
    avoidMrad_ = mrad;
  }
  uint32_t readings() const { return readings_; }
  uint32_t samples() const { return samples_; }
  uint32_t turnedMrad() const { return turnedMrad_; }

 private:
  enum class Phase : uint8_t { Idle, ToStart, Read, Step, ToWalls, Done };

  DriveAction turn(Phase next, int32_t mrad);
  DriveAction readNext();
  void noteEcho(Sensor s, int16_t cm);

  int32_t sweepMrad_, stepMrad_;
  int16_t approachFromCm_;
  Echo target_;
  bool avoiding_ = false;  // an approach was made (avoid())
  bool heard_ = false;     // some reading of this sweep had an echo (or one too near)
  int8_t approachesLeft_ = -1;  // begin()'s
  int32_t avoidMrad_ = 0;
  Phase phase_ = Phase::Idle;
  WallDirection walls_;
  WallDirectionEstimate result_;
  int32_t headingMrad_ = 0;  // since the start, as the encoders tell it (+ clockwise)
  int32_t commandMrad_ = 0;  // the rotation in progress
  int32_t targetMrad_ = 0;   // the heading to end on
  uint8_t sensor_ = 0;       // the next sensor to read at this heading
  bool stalled_ = false;     // a rotation of the sweep stalled (the body met something): the sweep ends there
  uint32_t readings_ = 0, samples_ = 0, turnedMrad_ = 0;
};

}  // namespace nxtmap
