#include "host/sim/SonarNoise.hpp"

#include <cstdio>

namespace nxtmap::sim {

namespace {

// The model the published figures were measured with (kept unchanged so they reproduce).
SonarNoise typical() {
  SonarNoise s;
  s.rangeSigmaCm = 1.0;
  s.biasCm = 0.5;
  s.dropoutProb = 0.01;
  s.specularMissProb = 0.02;
  s.specularAngleDeg = 60.0;
  s.crosstalkProb = 0.02;
  s.coneHalfAngleDeg = 5.0;
  return s;
}

// The LEGO 9846 sensor as measured. Sources: docs/nxt-sonar-and-odometry.md (each value names its own).
SonarNoise nxt() {
  SonarNoise s;
  s.rangeScale = 0.9757;     // jasonatwood.io/archives/137: fit reading = 0.9757 * true + 1.88 cm
  s.biasCm = 1.88;           // the same fit; the offset "likely systematic"
  s.poseErrorSigmaCm = 1.0;  // judgement: jasonatwood's RMSE 1.66 cm less its 1.08 cm mean error leaves
                             // ~1.2 cm (quantisation included); repeats at a pose agree (abukhiranm 2009-07)
  s.pingJitterCm = 0.5;      // judgement: readings repeat at a pose to the 1 cm quantisation (jasonatwood)
  s.nearFieldCm = 7.0;       // nxttime 2012-09-12: "the minimum range is about 7 cm"
  s.nearFieldMode = NearField::NoEcho;
  s.nearFieldHighCm = 2.0;    // leJOS forum p=11589: 3..21 cm read about +2 cm high (the ReadsHigh variant)
  s.reliableRangeCm = 160.0;  // nxttime, TU/e wiki: a wall is reliable within about 160 cm ...
  s.rangeLimitCm = 260.0;     // ... "often" seen to 2 m (echo probability 0.6 there), glass at 255 cm
  s.coneHalfAngleDeg = 10.0;  // judgement (half-angle 10-20 degrees, thenxtstep topic 256, TU/e wiki):
  s.coneWideDeg = 15.0;       //   narrow close, widest in between, only centred objects at the limit;
  s.coneWideAtCm = 60.0;      //   Moravec & Elfes' Polaroid cone is 15 degrees half-angle
  s.coneFarDeg = 5.0;
  s.specularAngleDeg = 90.0;       // off-axis grazing rays are handled by the incidence loss below
  s.incidenceLossStartDeg = 35.0;  // judgement: smooth walls go specular from about 30-40 degrees
  s.incidenceLossFullDeg = 60.0;   //   (Designing Autonomous Mobile Robots p.173; NXT scanner log 2009-06-21)
  s.incidenceLossMaxProb = 0.9;    //   Polaroid in a hallway: more than half the ranges too long or missing
  s.phantomProb = 0.3;             //   (Moravec "ROBOT" 1998 p.35); judgement: a third of losses come back long
  s.softRangeFactor = 0.6;         // TU/e wiki: a hand puppet 150 cm against glass 255 cm
  s.softEchoProb = 0.7;            // judgement: soft surfaces absorb (stemrobotics.cs.pdx.edu/node/385)
  s.thinRangeFactor = 0.4;         // judgement: thin legs are weak targets, seen late (TU/e wiki, stemrobotics)
  s.thinEchoProb = 0.5;            //   ... or not at all
  s.crosstalkProb = 0.5;           // judgement: sensors pinging together give wrong readings (rjmcnamara.com)
  s.crosstalkWindowMs = 50.0;      // judgement: a sensor listens 50 ms after its ping (leJOS single shot,
                                   // firmware kEchoMs); shorter than SonarModel::kPingMs (55 ms), so the
                                   // firmware's one-sensor-at-a-time sequence never cross-talks
  s.wildProb = 0.02;               // judgement: "a reasonable number of erroneous 0 and 255 returns" (FTC 5065)
  return s;
}

// Worse than any sensor we know of: the measured model with every magnitude pushed past its source.
SonarNoise harsh() {
  SonarNoise s = nxt();
  s.rangeSigmaCm = 1.0;
  s.dropoutProb = 0.05;
  s.poseErrorSigmaCm = 3.0;  // the vendor's +-3 cm (LEGO user guide) as one sigma
  s.nearFieldCm = 10.0;
  s.reliableRangeCm = 120.0;
  s.rangeLimitCm = 200.0;
  s.coneHalfAngleDeg = 12.0;
  s.coneWideDeg = 20.0;
  s.coneFarDeg = 8.0;
  s.incidenceLossStartDeg = 25.0;
  s.incidenceLossFullDeg = 50.0;
  s.incidenceLossMaxProb = 1.0;
  s.phantomProb = 0.5;
  s.softRangeFactor = 0.4;
  s.softEchoProb = 0.5;
  s.thinRangeFactor = 0.3;
  s.thinEchoProb = 0.3;
  s.crosstalkProb = 0.8;
  s.crosstalkWindowMs = 80.0;  // longer than kPingMs: even the firmware's sequence cross-talks
  s.wildProb = 0.05;
  return s;
}

std::string line(const char* name, double value, const char* unit, const char* meaning) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%-22s %8g %-4s %s", name, value, unit, meaning);
  return buf;
}

}  // namespace

SonarNoise sonarPreset(const std::string& name) {
  if (name == "typical") return typical();
  if (name == "nxt" || name == "nxt-uncalibrated") return nxt();
  if (name == "harsh") return harsh();
  return SonarNoise{};
}

std::vector<std::string> describeSonar(const SonarNoise& s) {
  const bool high = s.nearFieldMode == NearField::ReadsHigh;
  return {
      line("rangeSigmaCm", s.rangeSigmaCm, "cm", "gaussian noise drawn per ping"),
      line("biasCm", s.biasCm, "cm", "offset of the linear error (reading = rangeScale * true + biasCm)"),
      line("dropoutProb", s.dropoutProb, "", "no echo, per ping"),
      line("specularMissProb", s.specularMissProb, "", "no echo when the axis echo is past specularAngleDeg"),
      line("specularAngleDeg", s.specularAngleDeg, "deg", "incidence past which off-axis rays return nothing"),
      line("crosstalkProb", s.crosstalkProb, "", "a bogus 3..50 cm echo when another sensor was heard"),
      line("coneHalfAngleDeg", s.coneHalfAngleDeg, "deg", "beam half-angle at 0 cm (0 = one ray)"),
      line("rangeScale", s.rangeScale, "", "slope of the linear error"),
      line("poseErrorSigmaCm", s.poseErrorSigmaCm, "cm", "error fixed per pose (repeat pings agree), sigma"),
      line("pingJitterCm", s.pingJitterCm, "cm", "per-ping error, uniform within +-"),
      line("poseErrorDraw", static_cast<double>(s.poseErrorDraw), "",
           "the pose error is fixed by 0 the pose, 1 the echo's range and incidence, 2 nothing (per ping)"),
      line("nearFieldCm", s.nearFieldCm, "cm", "echoes nearer than this are masked (0 = none)"),
      line("nearFieldReadsHigh", high ? 1.0 : 0.0, "", "1: near echoes read high instead of nothing"),
      line("nearFieldHighCm", s.nearFieldHighCm, "cm", "how much too far a near echo reads (variant 1)"),
      line("reliableRangeCm", s.reliableRangeCm, "cm", "a hard wall always echoes up to here (0 = no limit)"),
      line("rangeLimitCm", s.rangeLimitCm, "cm", "... and never past here (linear between)"),
      line("coneWideDeg", s.coneWideDeg, "deg", "widest beam half-angle (0 = the cone keeps its width)"),
      line("coneWideAtCm", s.coneWideAtCm, "cm", "range of the widest beam"),
      line("coneFarDeg", s.coneFarDeg, "deg", "beam half-angle at the farthest echo"),
      line("incidenceLossStartDeg", s.incidenceLossStartDeg, "deg", "hard faces lose echoes past this (0 = never)"),
      line("incidenceLossFullDeg", s.incidenceLossFullDeg, "deg", "... rising to the full loss here"),
      line("incidenceLossMaxProb", s.incidenceLossMaxProb, "", "the full loss probability"),
      line("phantomProb", s.phantomProb, "", "a lost hard echo returns after a second bounce (too long)"),
      line("softRangeFactor", s.softRangeFactor, "", "soft surfaces: range limits scaled by this"),
      line("softEchoProb", s.softEchoProb, "", "soft surfaces: echo probability within their range"),
      line("thinRangeFactor", s.thinRangeFactor, "", "thin targets: range limits scaled by this"),
      line("thinEchoProb", s.thinEchoProb, "", "thin targets: echo probability within their range"),
      line("crosstalkWindowMs", s.crosstalkWindowMs, "ms", "another sensor's ping this recent is heard"),
      line("wildProb", s.wildProb, "", "an erroneous 0, 255 or short reading, per ping"),
  };
}

}  // namespace nxtmap::sim
