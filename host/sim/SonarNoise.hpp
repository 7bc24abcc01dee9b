// SonarNoise: how the simulated NXT ultrasonic sensor deviates from the truth (the preset's sonar part).
// Fields up to coneHalfAngleDeg are the `typical` model the published figures were measured with; the
// rest model the measured sensor (nxt-sonar-and-odometry.md; each preset value cites its source in
// SonarNoise.cpp). A field at its default changes nothing and draws no random number. SonarModel applies them.
#pragma once

#include <string>
#include <vector>

namespace nxtmap::sim {

// What an echo from nearer than nearFieldCm reads.
enum class NearField {
  NoEcho,    // masked by the transducer's ringing: that part of the beam returns nothing
  ReadsHigh  // reads nearFieldHighCm too far (below kNearFieldBlindCm still nothing)
};

// What the error fixed per pose (SonarNoise::poseErrorSigmaCm) is drawn by. The presets keep PerPose, the
// harshest reading of the sources (a robot moving along a wall meets a new error at every stop); the others are
// what-ifs for the bench (bench::lessOneTable).
enum class PoseErrorDraw : uint8_t {
  PerPose,      // the face to ~1 cm and the axis to ~1 degree, per sensor: repeat pings agree, any move redraws it
  PerGeometry,  // the echo's range to ~1 cm and its incidence to ~1 degree, per sensor: the same wall at the same
                // distance reads the same error wherever along it
  PerPing,      // drawn afresh at every ping (it averages out over repeats)
};

struct SonarNoise {
  // --- the `typical` model (kept so the published figures reproduce) ---
  double rangeSigmaCm = 0.0;      // gaussian range noise drawn per ping, cm (>= 0)
  double biasCm = 0.0;            // added to every echo, cm: the offset of the linear error
  double dropoutProb = 0.0;       // 0..1: 255 instead of an echo, per ping
  double specularMissProb = 0.0;  // 0..1: 255 when the axis echo's incidence exceeds specularAngleDeg
  double specularAngleDeg = 0.0;  // 0..90, angle between the ray and the hit face's normal; off-axis rays
                                  // meeting a face beyond it return nothing
  double crosstalkProb = 0.0;     // 0..1: a bogus short echo (3..50 cm) when another sensor pings together
                                  // with this one or within crosstalkWindowMs before it
  double coneHalfAngleDeg = 0.0;  // beam half-angle at 0 cm, degrees; 0 = a single ray along the axis

  // --- the measured sensor ---
  double rangeScale = 1.0;        // slope of the linear error: reading = rangeScale * true + biasCm
  double poseErrorSigmaCm = 0.0;  // error fixed per pose (face to ~1 cm, axis to ~1 degree), gaussian, cm
  double pingJitterCm = 0.0;      // per-ping error, uniform in +-pingJitterCm, cm (0..0.5 keeps repeats
                                  // within 1 cm)
  PoseErrorDraw poseErrorDraw = PoseErrorDraw::PerPose;  // what poseErrorSigmaCm is fixed by (what-ifs aside: pose)
  double nearFieldCm = 0.0;       // echoes nearer than this are affected (nearFieldMode), cm; 0 = none
  NearField nearFieldMode = NearField::NoEcho;
  double nearFieldHighCm = 2.0;        // ReadsHigh: how much too far a near echo reads, cm
  double reliableRangeCm = 0.0;        // a hard wall always echoes up to here, cm; 0 = no range limit
  double rangeLimitCm = 0.0;           // ... and never beyond here; the echo probability falls linearly
                                       // between, cm (> reliableRangeCm when reliableRangeCm > 0)
  double coneWideDeg = 0.0;            // widest beam half-angle, reached at coneWideAtCm, degrees; 0 = the
                                       // beam keeps coneHalfAngleDeg at every range
  double coneWideAtCm = 0.0;           // range of the widest beam, cm
  double coneFarDeg = 0.0;             // beam half-angle at the farthest echo (reach), degrees
  double incidenceLossStartDeg = 0.0;  // hard surfaces: echo loss starts when the sensor's axis is turned
                                       // past this from the face's normal, degrees; 0 = no such loss
  double incidenceLossFullDeg = 90.0;  // ... and reaches incidenceLossMaxProb here, degrees
  double incidenceLossMaxProb = 0.0;   // 0..1: the loss probability at and past incidenceLossFullDeg
  double phantomProb = 0.0;            // 0..1: a lost hard echo returns after a second bounce (reads the
                                       // whole path, too long)
  double softRangeFactor = 1.0;        // soft surfaces: the range limits scaled by this (0..1]
  double softEchoProb = 1.0;           // 0..1: soft surfaces echo with this probability inside their range
  double thinRangeFactor = 1.0;        // thin targets (legs): the range limits scaled by this (0..1]
  double thinEchoProb = 1.0;           // 0..1: thin targets echo with this probability inside their range
  double crosstalkWindowMs = 0.0;      // another sensor's ping this long before this one is heard, ms;
                                       // 0 = only a ping at the same moment
  double wildProb = 0.0;               // 0..1 per ping: an erroneous 0, 255 or short reading (a third each)
};

// Below this an echo reads nothing even in NearField::ReadsHigh, cm (leJOS forum viewtopic.php?p=11589:
// 3..21 cm read about +2 cm high, 2 cm read 255 or a wild value).
constexpr double kNearFieldBlindCm = 3.0;

// The sonar part of preset `name` ("ideal", "typical", "nxt", "nxt-uncalibrated", "harsh"; anything
// else gives ideal).
SonarNoise sonarPreset(const std::string& name);
// One line per field: "name value unit  meaning", for `nxtmap sim --noise list`.
std::vector<std::string> describeSonar(const SonarNoise& s);

}  // namespace nxtmap::sim
