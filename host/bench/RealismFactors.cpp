// Table 2 of the realism section: `typical` plus one measured fact of `nxt` at a time (the values are the
// presets' own: sim::sonarPreset("nxt"), sim::wheelPreset("nxt") and ("nxt-uncalibrated")), each row against
// its base row. Facts that only show where walls are met obliquely (specular loss) or with furniture (soft and
// thin surfaces) are also run in the misaligned published rooms and the furnished rooms.
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "host/bench/RealismBench.hpp"
#include "host/cli/Args.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::bench {
namespace {
using report::formatNumber;

constexpr int kFactorSeeds = 10;  // seeds 1..10 for every row

struct Factor {
  std::string name;
  const RealismSet* set = nullptr;
  RealismVariant variant;
  int base = -1;  // the row it is measured against (-1: a base row)
};

struct Measured {
  Tally byStrategy[2];  // propagation, frontier
};

using SonarEdit = std::function<void(sim::SonarNoise&)>;
using WheelEdit = std::function<void(sim::WheelNoise&)>;

RealismVariant typicalWith(const SonarEdit& sonar, const WheelEdit& wheels = {}) {
  RealismVariant v = presetVariant("typical");
  if (sonar) sonar(v.noise.sonar);
  if (wheels) wheels(v.noise.wheels);
  return v;
}

RealismVariant misaligned(double deg, double offsetCells) {
  RealismVariant v = presetVariant("typical");
  v.misalignDeg = deg;
  v.offsetCells = offsetCells;
  return v;
}

// The factors, base rows first in each group.
std::vector<Factor> factors(const RealismSet& published, const RealismSet& brick, const RealismSet& furnished) {
  // Values: the presets' own.
  const sim::SonarNoise n = sim::sonarPreset("nxt"), h = sim::sonarPreset("harsh");
  const sim::WheelNoise cal = sim::wheelPreset("nxt"), unc = sim::wheelPreset("nxt-uncalibrated");
  const auto cone = [n](sim::SonarNoise& s) {
    s.coneHalfAngleDeg = n.coneHalfAngleDeg;
    s.coneWideDeg = n.coneWideDeg;
    s.coneWideAtCm = n.coneWideAtCm;
    s.coneFarDeg = n.coneFarDeg;
  };
  const auto specular = [n](sim::SonarNoise& s) {
    s.incidenceLossStartDeg = n.incidenceLossStartDeg;
    s.incidenceLossFullDeg = n.incidenceLossFullDeg;
    s.incidenceLossMaxProb = n.incidenceLossMaxProb;
    s.phantomProb = n.phantomProb;
  };
  const auto crosstalk = [n](sim::SonarNoise& s) {
    s.crosstalkProb = n.crosstalkProb;
    s.crosstalkWindowMs = n.crosstalkWindowMs;
  };
  const auto poseError = [n](sim::SonarNoise& s) {
    s.poseErrorSigmaCm = n.poseErrorSigmaCm;
    s.pingJitterCm = n.pingJitterCm;
  };
  const auto rangeLimit = [n](sim::SonarNoise& s) {
    s.reliableRangeCm = n.reliableRangeCm;
    s.rangeLimitCm = n.rangeLimitCm;
  };
  const auto surfaces = [n](sim::SonarNoise& s) {
    s.softRangeFactor = n.softRangeFactor;
    s.softEchoProb = n.softEchoProb;
    s.thinRangeFactor = n.thinRangeFactor;
    s.thinEchoProb = n.thinEchoProb;
  };
  RealismVariant together = typicalWith(crosstalk);
  together.sensorsTogether = true;
  // The brick with another body (0 x 0: a point); the furnished rooms' factors are measured on the point so
  // that the body's own loss (the brick rows) does not drown them.
  const auto body = [&brick](RealismVariant v, double lengthCm, double widthCm) {
    v.robot = brick.robot;
    v.robot->bodyLengthCm = lengthCm;
    v.robot->bodyWidthCm = widthCm;
    return v;
  };
  const auto point = [&body](RealismVariant v) { return body(std::move(v), 0.0, 0.0); };
  RealismVariant misalignedSpecular = typicalWith(specular);
  misalignedSpecular.misalignDeg = 10.0;

  std::vector<Factor> f;
  const auto add = [&f](std::string name, const RealismSet& set, RealismVariant v, int base) {
    f.push_back({std::move(name), &set, std::move(v), base});
    return static_cast<int>(f.size()) - 1;
  };
  const int b = add("typical, square (base; misalignment 0 deg)", published, presetVariant("typical"), -1);
  add("+ cone (nxt: 10 -> 15 deg at 60 cm -> 5 deg)", published, typicalWith(cone), b);
  add("+ near field: no echo < 7 cm", published, typicalWith([n](sim::SonarNoise& s) {
        s.nearFieldCm = n.nearFieldCm;
        s.nearFieldMode = sim::NearField::NoEcho;
      }),
      b);
  add("+ near field: reads +2 cm high < 7 cm", published, typicalWith([n](sim::SonarNoise& s) {
        s.nearFieldCm = n.nearFieldCm;
        s.nearFieldMode = sim::NearField::ReadsHigh;
        s.nearFieldHighCm = n.nearFieldHighCm;
      }),
      b);
  add("+ per-pose error (1 cm fixed, +-0.5 per ping)", published, typicalWith(poseError), b);
  add("+ per-pose + linear error (0.9757 x + 1.88)", published, typicalWith([n, poseError](sim::SonarNoise& s) {
        poseError(s);
        s.rangeScale = n.rangeScale;
        s.biasCm = n.biasCm;
      }),
      b);
  add("+ range limit (reliable 160, none past 260 cm)", published, typicalWith(rangeLimit), b);
  add("+ specular loss (35-60 deg, 0.9; phantom 0.3)", published, typicalWith(specular), b);
  add("+ cross-talk fields, firmware schedule", published, typicalWith(crosstalk), b);
  add("+ cross-talk, sensors together", published, together, b);
  add("+ cross-talk, harsh's 80 ms window, firmware schedule", published, typicalWith([h](sim::SonarNoise& s) {
        s.crosstalkProb = h.crosstalkProb;
        s.crosstalkWindowMs = h.crosstalkWindowMs;
      }),
      b);
  add("+ wild readings (2 %)", published, typicalWith([n](sim::SonarNoise& s) { s.wildProb = n.wildProb; }), b);
  add("+ track width 2 % (uncalibrated Eb)", published,
      typicalWith({}, [unc](sim::WheelNoise& w) { w.trackError = unc.trackError; }), b);
  add("+ wheel ratio 2 deg/m (uncalibrated Ed)", published,
      typicalWith({}, [unc](sim::WheelNoise& w) { w.diameterRatioError = unc.diameterRatioError; }), b);
  add("+ track + ratio, calibrated (nxt: a quarter)", published,
      typicalWith({},
                  [cal](sim::WheelNoise& w) {
                    w.trackError = cal.trackError;
                    w.diameterRatioError = cal.diameterRatioError;
                  }),
      b);
  add("+ backlash 2 deg + encoder 1 deg", published,
      typicalWith({},
                  [cal](sim::WheelNoise& w) {
                    w.encoderDeg = cal.encoderDeg;
                    w.backlashDeg = cal.backlashDeg;
                  }),
      b);
  add("misaligned 3 deg", published, misaligned(3.0, 0.0), b);
  add("misaligned 10 deg", published, misaligned(10.0, 0.0), b);
  add("offset 1/3 cell, square", published, misaligned(0.0, 1.0 / 3.0), b);
  add("misaligned 10 deg + offset 1/3 cell", published, misaligned(10.0, 1.0 / 3.0), b);
  add("all of nxt (the preset)", published, presetVariant("nxt"), b);
  add("all of nxt-uncalibrated (the preset)", published, presetVariant("nxt-uncalibrated"), b);
  const int bm = add("typical, misaligned 10 deg (base)", published, misaligned(10.0, 0.0), -1);
  add("+ specular loss", published, misalignedSpecular, bm);
  const int bb = add("typical, brick as a point (base)", brick, point(presetVariant("typical")), -1);
  add("body 12 x 12 cm (turns within 8.5 cm)", brick, body(presetVariant("typical"), 12.0, 12.0), bb);
  add("body 14 x 14 cm (turns within 9.9 cm)", brick, body(presetVariant("typical"), 14.0, 14.0), bb);
  add("body 16 x 18 cm (the brick's)", brick, presetVariant("typical"), bb);
  const int bf = add("typical, brick as a point (base)", furnished, point(presetVariant("typical")), -1);
  add("body 16 x 18 cm (the brick's)", furnished, presetVariant("typical"), bf);
  add("+ soft/thin surfaces (echo probability)", furnished, point(typicalWith(surfaces)), bf);
  add("+ soft/thin surfaces + range limit", furnished, point(typicalWith([surfaces, rangeLimit](sim::SonarNoise& s) {
        surfaces(s);
        rangeLimit(s);
      })),
      bf);
  add("+ specular loss", furnished, point(typicalWith(specular)), bf);
  add("+ cross-talk, sensors together", furnished, point(together), bf);
  return f;
}

std::vector<std::string> rowOf(const Factor& f, const std::string& strategy, const Tally& t, const Tally* base) {
  const bool isBase = base == nullptr;
  const Tally& b = isBase ? t : *base;
  const bool same = t.detected == b.detected && t.detectedAligned == b.detectedAligned && t.wrong == b.wrong &&
                    t.unsafeFree == b.unsafeFree && t.lost == b.lost && t.wrongAligned == b.wrongAligned;
  return {f.name,
          f.set->name,
          strategy,
          withDelta(t.mean(t.detected), b.mean(b.detected), 1, isBase),
          withDelta(t.mean(t.detectedAligned), b.mean(b.detectedAligned), 1, isBase),
          withDelta(t.mean(t.wrong), b.mean(b.wrong), 1, isBase),
          withDelta(t.mean(t.unsafeFree), b.mean(b.unsafeFree), 1, isBase),
          std::to_string(t.lost) + "/" + std::to_string(t.runs) +
              (isBase ? "" : " (" + formatDelta(t.lost - b.lost, 0) + ")"),
          isBase ? "base"
          : same ? "NO CHANGE"
                 : "measured"};
}

}  // namespace

void factorTable(const RealismWorlds& w) {
  RealismSet published = w.published, brick = w.brick, furnished = w.furnished;
  published.seeds = brick.seeds = furnished.seeds = kFactorSeeds;
  const std::vector<Factor> list = factors(published, brick, furnished);
  size_t total = 0;
  for (const Factor& f : list) total += 2 * f.set->starts.size() * static_cast<size_t>(f.set->seeds);
  std::vector<Measured> measured(list.size());
  {
    cli::ProgressLine progress(std::cerr, cli::stderrIsTerminal(), progressLabel("realism", "one factor at a time"),
                               total);
    for (size_t i = 0; i < list.size(); ++i) {
      for (size_t k = 0; k < 2; ++k) {
        const mapping::Strategy s = cli::parseStrategy(mapping::strategyNames()[k]);
        measured[i].byStrategy[k] = runRealism(*list[i].set, list[i].variant, s, [&] { progress.tick(); });
      }
    }
  }
  std::cout
      << "\nrealism 2: one factor at a time: `typical` plus one measured fact of `nxt` (its own values), seeds 1-"
      << kFactorSeeds << ", each row\nagainst its base row (difference in brackets). Means over runs; lost: runs "
      << "lost of runs. Misaligned: the start heading\nturned by DEG (+ on odd seeds, - on even), the offset moves "
      << "the start right and down inside its cell. published = the\n18 Appendix-A rooms at 10 cm (published "
      << "robot); brick = the same at 20 cm (brick robot); furnished = worlds/rooms with the brick's\n"
      << "cells and sensor mounts, as a point except in its body row.\n"
      << "NO CHANGE: not one number of the row differs from its base row.\n\n";
  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < list.size(); ++i) {
    if (list[i].base < 0 && i > 0) rows.push_back({});
    for (size_t k = 0; k < 2; ++k) {
      const Tally* base = list[i].base < 0 ? nullptr : &measured[static_cast<size_t>(list[i].base)].byStrategy[k];
      rows.push_back(rowOf(list[i], mapping::strategyNames()[k], measured[i].byStrategy[k], base));
    }
  }
  printColumns({"factor", "worlds", "strategy", "detected %", "aligned %", "wrong", "unsafe free", "lost", "result"},
               rows);
}

}  // namespace nxtmap::bench
