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
  // A filtered reading of a known wall face: the NXT sensor's error fixed per pose (1 cm), +-0.5 cm per ping and
  // the whole-cm reading, sqrt(100 + 8 + 8) mm (docs/nxt-sonar-and-odometry.md).
  int32_t readingMm = 11;
  // Readings further than this from the prediction are not trusted (the pilot may raise it with its
  // cell: PilotConfig::gateCellTenths).
  int32_t gateMm = 40;
  // ... unless the landmark is a straight wall face and the filter itself is that unsure: up to this
  // far (mm) and within 2 sigma of the prediction (a robot that drifted unseen across open space).
  int32_t wideGateMm = 120;
  // A straight face refused between gateMm and wideGateMm is remembered; the next such refusal along
  // the same axis that moves the robot the same way confirms it: the filter was sure of a wrong
  // offset (a drift it corrected against a wall mapped a cell off), so it widens its variance along
  // the axis to that offset and accepts. false: every refusal is final.
  bool confirmWide = true;
};

// What the wheels' systematic errors are believed to be (UMBmark's Ed and Eb), and how well: learnt by the
// tracker from the walls, carried from run to run and room to room, kept on the brick. The defaults are an
// uncalibrated NXT's magnitudes (docs/nxt-sonar-and-odometry.md: about 2 deg/m of drift, turns 2 % off).
struct WheelCalibration {
  // Heading change per metre driven forward (+ clockwise), microradians per metre (|.| < 200,000), and
  // its variance ((urad/m)^2; 35,000 urad/m = 2 deg/m, 1 sigma).
  int32_t driftUradPerM = 0;
  int64_t driftVariance = 35000LL * 35000;
  // How far turns are off (actual / commanded - 1, ppm, |.| < 100,000: + turns too far), and its
  // variance (ppm^2; 20,000 ppm = 2 %, 1 sigma).
  int32_t turnPpm = 0;
  int64_t turnVariance = kUnknownTurnVariance;
  static constexpr int64_t kUnknownTurnVariance = 20000LL * 20000;
  // Nothing better than an uncalibrated NXT's turn error is known (nothing stored, nothing measured or learnt).
  constexpr bool turnsUnknown() const { return turnVariance >= kUnknownTurnVariance; }
};

// PoseTracker: a small Kalman filter, in integers, of where the robot really is relative to the
// cell and heading the explorer believes in. State, in the explorer's frame:
//   x, y   offset of the robot's centre from the believed cell's centre, mm (East, North);
//   theta  actual heading minus the believed axis heading, mrad, + = clockwise;
// and, except in the RAM-run image (no room), the wheels' systematic errors (WheelCalibration):
//   drift  heading change per metre driven forward, 0.1 mrad/m (a straight drive curves);
//   turn   how far the turns are off beyond what the caller already corrects, 10 ppm.
// Motion makes it uncertain; a reading of a wall the map already knows makes it certain again, and the
// walls seen before and after turns and along runs teach it the drift and the turn error.
// Small angles throughout (|theta| stays well under 0.3 rad): sin t = t, cos t = 1.
class PoseTracker {
 public:
#ifdef NXTMAP_NO_START_SQUARING
  static constexpr int kStates = 3;
#else
  static constexpr int kStates = 5;
  static constexpr int kDrift = 3, kTurn = 4;  // the wheels' states' indices
#endif

  explicit PoseTracker(const PoseNoise& noise = PoseNoise{}, const WheelCalibration& wheels = WheelCalibration{});

  // Exactly at the centre and, to `thetaVarianceMrad2` (mrad^2; 0: exactly), on the axis (the start
  // of a run; a robot handed over by another pilot keeps that pilot's heading uncertainty). What was
  // learnt of the wheels is kept.
  void reset(int64_t thetaVarianceMrad2 = 0);
  // What is believed of the wheels: the drift the tracker predicts and learns; turnPpm is the part of the
  // turn error the caller does not yet correct (see takeTurnPpm).
  WheelCalibration wheels() const;
  // Hands the learnt turn error (ppm) to the caller, who corrects every turn by it from now on: the
  // tracker's own turn error becomes 0 (its variance stays). 0 in the RAM-run image.
  int32_t takeTurnPpm();
  // The turn error has just been measured (and handed to the caller) to this variance (ppm^2).
  void knowTurn(int64_t variancePpm2);
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

  int32_t xMm() const { return static_cast<int32_t>(s_[0]); }
  int32_t yMm() const { return static_cast<int32_t>(s_[1]); }
  int32_t thetaMrad() const { return static_cast<int32_t>(s_[2]); }
  // Offset along d in mm (+ = towards d).
  int32_t along(Dir d) const { return static_cast<int32_t>(dx(d) * s_[0] + dy(d) * s_[1]); }
  // Variance of the offset along d's axis (mm^2) and of theta (mrad^2).
  int64_t varianceAlong(Dir d) const { return isVertical(d) ? p_[1][1] : p_[0][0]; }
  int64_t thetaVariance() const { return p_[2][2]; }
  // The predicted heading change of a drive of `mm` (mrad, + clockwise): the drift learnt.
  int32_t driftMrad(int32_t mm) const;
  // Readings accepted and rejected by the gate.
  uint32_t accepted() const { return accepted_; }
  uint32_t rejected() const { return rejected_; }

 private:
  // Motion by x' = F x: F's entries times kScale (identity: kScale), applied to the covariance.
  static constexpr int64_t kScale = 10000;
  void propagate(const int64_t (&f)[kStates][kStates]);
  // The Kalman update by a measurement of state `k` times `sign`, with innovation and its variance;
  // `teach`: it may also correct the wheels' states.
  void update(int k, int64_t sign, int64_t innovation, int64_t spread, bool teach);
  void turnHeading(int64_t urad);  // adds to theta, keeping what is below the mrad
  void drovePiece(int32_t mm, Dir heading);

  PoseNoise noise_;
  int64_t s_[kStates] = {};           // x mm, y mm, theta mrad[, drift 0.1 mrad/m, turn 10 ppm]
  int64_t residualUrad_ = 0;          // heading error below the mrad, microradians (|.| <= 500)
  int64_t p_[kStates][kStates] = {};  // covariance in the states' units
  uint32_t accepted_ = 0, rejected_ = 0;
  // Per axis (x, y): the sign (+1, -1) of the correction a refused straight face asked for, 0: none.
  int8_t refusedWide_[2] = {0, 0};
};

}  // namespace nxtmap
