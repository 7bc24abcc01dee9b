// WheelNoise: how the simulated NXT wheels and encoders deviate from the commanded motion (the preset's
// wheel part). slipSigma and turnSigmaDeg are the `typical` model the published figures were measured
// with; the rest model the measured NXT drive (encoder counts, backlash, UMBmark's systematic errors,
// nxt-sonar-and-odometry "The motors and odometry"). WheelModel applies them. A field at its default
// changes nothing and draws no random number.
//
// Sign conventions (UMBmark, Borenstein & Feng 1995), heading clockwise positive:
//   Ed = D_right / D_left, the wheel-diameter ratio. Ed > 1: the right wheel rolls farther, a straight
//        drive curves to the left (the heading drifts counter-clockwise, negative). The mean diameter
//        stays nominal: D_right = D (1 + e/2), D_left = D (1 - e/2) with e = +-diameterRatioError, so
//        Ed - 1 = e to first order and either sign drifts by the same amount.
//   Eb = b_actual / b_nominal, the effective track-width ratio. Eb > 1: every turn falls short by the
//        factor 1 / Eb (the pilot turns the wheels for the nominal track).
// The preset gives the magnitudes; each robot's signs come from its seed (WheelModel).
#pragma once

#include <string>
#include <vector>

namespace nxtmap::sim {

struct WheelNoise {
  double slipSigma = 0.0;           // relative distance error per straight move, 1 sigma (0.02 = 2 %)
  double turnSigmaDeg = 0.0;        // gaussian turn error per 90 degree turn, degrees (1 sigma)
  double encoderDeg = 0.0;          // encoder count, degrees of motor rotation (0 = continuous); a
                                    // simulated pilot stops each wheel on a whole count
  double backlashDeg = 0.0;         // gear play per wheel, degrees of motor rotation: after a wheel's
                                    // direction reverses, this much motor rotation does not move the wheel
  double diameterRatioError = 0.0;  // |D_right - D_left| / D (>= 0), about |Ed - 1|
  double trackError = 0.0;          // |Eb - 1| (>= 0), effective track-width error
};

// The NXT drive as built (RobotDescription, firmware MotionGeometry): 56 mm tyres, 112 mm track.
constexpr double kNxtWheelDiameterCm = 5.6;
constexpr double kNxtTrackCm = 11.2;

// diameterRatioError that makes a straight drive drift degPerMetre on a track of trackCm, and back.
double diameterRatioErrorForDrift(double degPerMetre, double trackCm);
double driftDegPerMetre(double diameterRatioError, double trackCm);

// The wheel part of preset `name` ("ideal", "typical", "nxt", "nxt-uncalibrated", "harsh"); all fields 0
// for any other name.
WheelNoise wheelPreset(const std::string& name);
// One line per field: "name value unit  meaning", for `nxtmap sim --noise list`.
std::vector<std::string> describeWheels(const WheelNoise& w);

}  // namespace nxtmap::sim
