// WheelModel: the two driven NXT wheels between the pilot's command and the ground. A command (SimRobot)
// or the emulated motors (DriveModel) turn each motor; the wheel follows through the gear play
// (backlash), rolls its own diameter (UMBmark Ed), slips, and the heading turns over the robot's actual
// track (UMBmark Eb). The parameters and their sign conventions are WheelNoise's; the per-robot signs of
// Ed and Eb come from a hash of the seed, so they never draw from a random stream.
// Random draws, all through the caller's rng and only for a non-zero sigma: straight() draws one slip
// (slipSigma), spin() and turnEighths() one turn error (turnSigmaDeg), newStretch() one of either. With only
// slipSigma and turnSigmaDeg set this is exactly the `typical` model the published figures used.
// Units: cm, degrees; heading clockwise positive; wheel 0 = left, 1 = right.
#pragma once

#include "host/sim/WheelNoise.hpp"

#include <array>
#include <cstdint>
#include <random>

namespace nxtmap::sim {

// The actual motion of one command: an arc of distanceCm (signed, + forward) over which the heading
// changes linearly by headingChangeDeg = headingWheelsDeg + headingNoiseDeg. The two parts are given so a
// caller can add them in the order the published model did: (heading + wheels) + noise.
struct WheelStep {
  double distanceCm = 0.0;
  double headingChangeDeg = 0.0;
  double headingWheelsDeg = 0.0;  // what the wheels' arcs give (commanded turn, Eb, Ed, backlash, counts)
  double headingNoiseDeg = 0.0;   // the random turn error (turnSigmaDeg)
  // A spin's turn as the encoders count it: whole counts (WheelNoise::encoderDeg) of each motor over the nominal
  // geometry, what a brick's drive layer reports (deg, + clockwise); the commanded turn exactly without encoders.
  double countedDeg = 0.0;
};

class WheelModel {
 public:
  WheelModel(const WheelNoise& noise, double wheelDiameterCm, double trackCm, uint64_t seed);

  // Commanded straight drive of cm (+ forward): both motors turn cm / (pi D) turns.
  WheelStep straight(double cm, std::mt19937_64& rng);
  // Commanded spin on the spot by deg, + clockwise: the left motor forward, the right one back.
  WheelStep spin(double deg, std::mt19937_64& rng);
  // The discrete turn of 45 degrees * eighths (its turn error is turnSigmaDeg whatever the angle).
  WheelStep turnEighths(int eighths, std::mt19937_64& rng);

  // The emulator: the motors turned the left/right encoders by these degrees in one integration step;
  // the actual ground arcs of each wheel in cm (backlash, diameters, the stretch's slip).
  void arcs(double leftEncDeg, double rightEncDeg, double& leftCm, double& rightCm);
  // The emulator's stretch: one move of the motors from rest to rest (DriveModel), with the random errors of
  // one command. A straight stretch (spin false) rolls one slip factor N(1, slipSigma) for arcs(), as
  // straight() does; a spin carries one turn error, as spin() does: after a nominal turn of theta degrees
  // it is z * turnSigmaDeg * max(0.25, |theta| / 90), z ~ N(0, 1) drawn here.
  void newStretch(bool spin, std::mt19937_64& rng);
  // The turn error (deg, + clockwise) a spin stretch gains with a further nominalDeg of turn; 0 otherwise.
  double stretchTurnNoiseDeg(double nominalDeg);

  double trackCm() const { return trackCm_ * trackRatio_; }  // the actual track (Eb applied)
  double nominalTrackCm() const { return trackCm_; }
  double cmPerMotorDeg() const { return cmPerDeg_; }  // nominal wheel arc per motor degree
  double diameterRatio() const;                       // this robot's Ed (right / left)
  double trackRatio() const { return trackRatio_; }   // this robot's Eb (actual / nominal)
  // What this robot's wheels do systematically, in the units the pilot learns them in (WheelCalibration):
  // actual / commanded turn - 1, and the heading change per metre driven forward (rad/m, + clockwise).
  double systematicTurnError() const;
  double systematicDriftRadPerM() const;
  const WheelNoise& noise() const { return noise_; }

 private:
  // The wheel's share of a commanded motor rotation of motorDeg: the count it stops on, less the gear
  // play taken up; 1 exactly when neither applies.
  double achieved(int wheel, double motorDeg);
  // Wheel rotation for a motor rotation of motorDeg through wheel's gear play (updates the play).
  double throughPlay(int wheel, double motorDeg);
  double turnError(double sigma, std::mt19937_64& rng) const;
  WheelStep turnBy(double deg, double noiseSigma, std::mt19937_64& rng);

  WheelNoise noise_;
  double cmPerDeg_;                   // pi D / 360
  double trackCm_;                    // nominal
  double trackRatio_ = 1.0;           // Eb
  std::array<double, 2> diameter_{};  // each wheel's diameter / nominal (1 -+ e/2)
  std::array<double, 2> play_{};      // motor minus wheel, motor degrees, within +-backlash/2
  double slip_ = 1.0;                 // the current stretch's factor (arcs())
  double turnZ_ = 0.0;                // the current spin stretch's turn error in sigmas (0: none)
  double stretchTurnDeg_ = 0.0;       // nominal turn of the current stretch so far, deg
  double stretchNoiseDeg_ = 0.0;      // turn error given for it so far, deg
};

}  // namespace nxtmap::sim
