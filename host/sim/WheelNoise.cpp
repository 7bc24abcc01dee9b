#include "host/sim/WheelNoise.hpp"

#include <cmath>
#include <cstdio>

namespace nxtmap::sim {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The measured NXT drive, docs/nxt-sonar-and-odometry.md "The motors and odometry":
constexpr double kEncoderDeg = 1.0;   // 360 counts a turn (NXT user guide p.31, bricks.stackexchange 9884)
constexpr double kBacklashDeg = 2.0;  // about +-2 degrees at each start, stop or reversal (xn--schler-dya.net)
// UMBmark magnitudes of an uncalibrated robot with rubber tyres (judgement from Borenstein & Feng 1995,
// solderspot 2014-05-08, nxtcodehelp "curving robot"): Eb about 2 % (a 90 degree turn off by about 1.8
// degrees), Ed giving about 2 degrees per metre; a UMBmark calibration leaves about a quarter of both.
constexpr double kUncalibratedTrackError = 0.02;
constexpr double kUncalibratedDriftDegPerM = 2.0;
constexpr double kCalibratedShare = 0.25;

// Random slip and turn error: the `typical` model the published figures were measured with (our own
// judgement, kept so those figures reproduce); the measured presets keep it as their random part.
constexpr double kTypicalSlip = 0.01;
constexpr double kTypicalTurnSigmaDeg = 0.5;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string line(const char* name, double value, const char* unit, const std::string& meaning) {
  return std::string(name) + " " + fmt(value) + " " + unit + "  " + meaning;
}

}  // namespace

double diameterRatioErrorForDrift(double degPerMetre, double trackCm) {
  // Over 100 cm the wheels' arcs differ by e * 100 cm: the heading turns e * 100 / track radians.
  return degPerMetre * kPi / 180.0 * trackCm / 100.0;
}

double driftDegPerMetre(double diameterRatioError, double trackCm) {
  return diameterRatioError * 100.0 / trackCm * 180.0 / kPi;
}

WheelNoise wheelPreset(const std::string& name) {
  WheelNoise w;
  if (name == "typical") {
    w.slipSigma = kTypicalSlip;
    w.turnSigmaDeg = kTypicalTurnSigmaDeg;
  } else if (name == "nxt" || name == "nxt-uncalibrated") {
    const double share = name == "nxt" ? kCalibratedShare : 1.0;
    w.slipSigma = kTypicalSlip;
    w.turnSigmaDeg = kTypicalTurnSigmaDeg;
    w.encoderDeg = kEncoderDeg;
    w.backlashDeg = kBacklashDeg;
    w.trackError = share * kUncalibratedTrackError;
    w.diameterRatioError = diameterRatioErrorForDrift(share * kUncalibratedDriftDegPerM, kNxtTrackCm);
  } else if (name == "harsh") {
    // Worse than any robot we know of: three times typical's slip, four times its turn error, twice
    // the uncalibrated UMBmark errors and the measured backlash.
    w.slipSigma = 0.03;
    w.turnSigmaDeg = 2.0;
    w.encoderDeg = kEncoderDeg;
    w.backlashDeg = 2.0 * kBacklashDeg;
    w.trackError = 2.0 * kUncalibratedTrackError;
    w.diameterRatioError = diameterRatioErrorForDrift(2.0 * kUncalibratedDriftDegPerM, kNxtTrackCm);
  }
  return w;
}

std::vector<std::string> describeWheels(const WheelNoise& w) {
  return {
      line("slipSigma", w.slipSigma, "(fraction)", "random distance error of a straight move, 1 sigma"),
      line("turnSigmaDeg", w.turnSigmaDeg, "deg", "random error of a 90 degree turn, 1 sigma"),
      line("encoderDeg", w.encoderDeg, "deg", "encoder count (0 = continuous); the pilot stops on whole counts"),
      line("backlashDeg", w.backlashDeg, "deg", "gear play: motor rotation lost at each wheel reversal"),
      line("diameterRatioError", w.diameterRatioError, "(fraction)",
           "|Ed - 1| wheel-diameter ratio error, sign per robot: a straight drive drifts " +
               fmt(driftDegPerMetre(w.diameterRatioError, kNxtTrackCm)) + " deg/m on the NXT track"),
      line("trackError", w.trackError, "(fraction)",
           "|Eb - 1| track-width error, sign per robot: a 90 degree turn is off by about " + fmt(90.0 * w.trackError) +
               " deg"),
  };
}

}  // namespace nxtmap::sim
