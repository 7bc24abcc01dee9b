#pragma once
#include <cstdint>

#include "common/grid/Cell.hpp"

namespace nxtmap {

// How much the wheels and sensors are trusted (1 sigma each). Defaults fit an NXT with
// tachometer-controlled motion on a smooth floor; they may be pessimistic, never zero.
struct PoseNoise {
  int32_t turnMradPerQuarter = 12;  // heading error of a 90 deg turn (smaller turns: less, floor 1/4)
  int32_t slipPerMille = 20;        // along-track error per mm driven
  int32_t driveMradPerCell = 3;     // heading error picked up per cell driven
  int32_t readingMm = 8;            // a filtered reading of a known wall face
  int32_t gateMm = 40;              // readings further than this from the prediction are not trusted
  // ... unless the landmark is a straight wall face and the filter itself is that unsure: up to this
  // far (mm) and within 2 sigma of the prediction (a robot that drifted unseen across open space).
  int32_t wideGateMm = 120;
  // A straight face refused between gateMm and wideGateMm is remembered; the next such refusal along
  // the same axis that moves the robot the same way confirms it: the filter was sure of a wrong
  // offset (a drift it corrected against a wall mapped a cell off), so it widens its variance along
  // the axis to that offset and accepts. false: every refusal is final.
  bool confirmWide = true;
};

// PoseTracker: a small Kalman filter, in integers, of where the robot really is relative to the
// cell and heading the explorer believes in. State, in the explorer's frame:
//   x, y   offset of the robot's centre from the believed cell's centre, mm (East, North);
//   theta  actual heading minus the believed axis heading, mrad, + = clockwise.
// Motion makes it uncertain; a reading of a wall the map already knows makes it certain again.
// Small angles throughout (|theta| stays well under 0.3 rad): sin t = t, cos t = 1.
class PoseTracker {
 public:
  explicit PoseTracker(const PoseNoise& noise = PoseNoise{}) : noise_(noise) {}

  // Exactly at the centre and, to `thetaVarianceMrad2` (mrad^2; 0: exactly), on the axis (the start
  // of a run; a robot handed over by another pilot keeps that pilot's heading uncertainty).
  void reset(int64_t thetaVarianceMrad2 = 0);
  // The robot stands xMm east and yMm north of its cell's centre, known as well as one reading (after reset).
  void place(int32_t xMm, int32_t yMm);

  // The robot turned in place by `mrad` (clockwise +) while the believed heading changed by
  // `quarters` quarter turns.
  void rotated(int32_t mrad, int quarters);
  // The robot drove `mm` (signed, + forward) facing `heading` (the believed axis heading).
  void drove(int32_t mm, Dir heading);
  // The explorer now believes it is `cells` further along `d`: move the reference centre.
  void rebase(Dir d, int cells, int32_t cellMm);
  // A measurement of the offset along `d` (mm, + = towards d), with extra variance (mm^2) on top
  // of the reading's own (the landmark's uncertainty). `straightFace`: the landmark is a straight
  // wall across the beam, trusted up to PoseNoise::wideGateMm, and a second such reading agreeing with
  // a refused one is taken (PoseNoise::confirmWide). Returns false when gated out.
  bool measure(Dir d, int32_t offsetMm, int32_t extraVarianceMm2 = 0, bool straightFace = false);
  // A direct measurement of theta (mrad) with its variance (mrad^2), e.g. from a straight wall
  // read twice along a run. Returns false when gated out (3 sigma).
  bool measureHeading(int32_t thetaMrad, int32_t varianceMrad2);
  int32_t readingVariance() const { return noise_.readingMm * noise_.readingMm; }
  int32_t gateMm() const { return noise_.gateMm; }

  int32_t xMm() const { return static_cast<int32_t>(x_); }
  int32_t yMm() const { return static_cast<int32_t>(y_); }
  int32_t thetaMrad() const { return static_cast<int32_t>(t_); }
  // Offset along d in mm (+ = towards d).
  int32_t along(Dir d) const { return static_cast<int32_t>(dx(d) * x_ + dy(d) * y_); }
  // Variance of the offset along d's axis (mm^2) and of theta (mrad^2).
  int64_t varianceAlong(Dir d) const { return isVertical(d) ? p_[1][1] : p_[0][0]; }
  int64_t thetaVariance() const { return p_[2][2]; }
  // Readings accepted and rejected by the gate.
  uint32_t accepted() const { return accepted_; }
  uint32_t rejected() const { return rejected_; }

 private:
  PoseNoise noise_;
  int64_t x_ = 0, y_ = 0, t_ = 0;  // mm, mm, mrad
  int64_t residualUrad_ = 0;       // heading error below the mrad, microradians (|.| <= 500)
  int64_t p_[3][3] = {};           // covariance: mm^2, mm*mrad, mrad^2
  uint32_t accepted_ = 0, rejected_ = 0;
  // Per axis (x, y): the sign (+1, -1) of the correction a refused straight face asked for, 0: none.
  int8_t refusedWide_[2] = {0, 0};
};

}  // namespace nxtmap
