// Table 3 of the realism section: the brick as the acceptance runs it (the 18 layouts at 20 cm, `nxt`, set down
// up to 10 degrees off square, squared by its sweep) with one measured fact of `nxt` taken away at a time, each
// row against the whole preset. Table 2 says what each fact costs a robot that has none of the others; this one
// says what each costs the robot as it is, which is where the work on localisation should go. Without the jitter
// the robot stands on its cell's centre square to the layouts' 20 cm walls: every face lies on a cell edge.
#include <algorithm>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "host/bench/RealismBench.hpp"
#include "host/cli/Args.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/sim/NoiseProfile.hpp"
#include "host/sim/RobotDescription.hpp"

namespace nxtmap::bench {
namespace {
using report::formatNumber;

constexpr int kLessOneSeeds = 10;    // seeds 1..10, as the acceptance's brick rooms
constexpr double kJitterDeg = 10.0;  // the acceptance's start jitter, degrees

struct LessOne {
  std::string name;
  sim::NoiseProfile noise;
  double jitterDeg = kJitterDeg;
};

std::vector<LessOne> lessOneRows() {
  const sim::NoiseProfile nxt = *sim::noiseProfileByName("nxt");
  std::vector<LessOne> rows;
  const auto add = [&rows, &nxt](std::string name, const std::function<void(sim::NoiseProfile&)>& edit) {
    LessOne r{std::move(name), nxt, kJitterDeg};
    if (edit) edit(r.noise);
    rows.push_back(std::move(r));
  };
  add("nxt, set down up to 10 deg off (base)", {});
  add("- error fixed per pose (1 cm)", [](sim::NoiseProfile& n) { n.sonar.poseErrorSigmaCm = 0.0; });
  add("  the same 1 cm fixed by range and incidence",
      [](sim::NoiseProfile& n) { n.sonar.poseErrorDraw = sim::PoseErrorDraw::PerGeometry; });
  add("  the same 1 cm drawn afresh each ping",
      [](sim::NoiseProfile& n) { n.sonar.poseErrorDraw = sim::PoseErrorDraw::PerPing; });
  add("- per-ping jitter (+-0.5 cm)", [](sim::NoiseProfile& n) { n.sonar.pingJitterCm = 0.0; });
  add("- linear error (0.9757 x + 1.88)", [](sim::NoiseProfile& n) {
    n.sonar.rangeScale = 1.0;
    n.sonar.biasCm = 0.0;
  });
  add("- wide cone (5 deg throughout)",
      [](sim::NoiseProfile& n) { n.sonar.coneHalfAngleDeg = n.sonar.coneWideDeg = n.sonar.coneFarDeg = 5.0; });
  add("- specular loss", [](sim::NoiseProfile& n) { n.sonar.incidenceLossMaxProb = 0.0; });
  add("- wild readings and cross-talk", [](sim::NoiseProfile& n) {
    n.sonar.wildProb = 0.0;
    n.sonar.crosstalkProb = 0.0;
  });
  add("- wheel ratio (drift)", [](sim::NoiseProfile& n) { n.wheels.diameterRatioError = 0.0; });
  add("- track width", [](sim::NoiseProfile& n) { n.wheels.trackError = 0.0; });
  add("- random slip and turn error", [](sim::NoiseProfile& n) {
    n.wheels.slipSigma = 0.0;
    n.wheels.turnSigmaDeg = 0.0;
  });
  add("- backlash", [](sim::NoiseProfile& n) { n.wheels.backlashDeg = 0.0; });
  rows.push_back(LessOne{"- start jitter (square, walls on cell edges)", nxt, 0.0});
  return rows;
}

Tally runRow(const cli::Suite& suite, const LessOne& row, mapping::Strategy strategy, cli::ProgressLine& progress) {
  cli::SuiteSettings s;
  s.strategy = strategy;
  s.noise = "nxt";
  s.robot = *sim::robotByName("brick");
  s.squareAtStart = true;
  Tally t;
  for (const report::Scenario& sc : suite.scenarios) {
    for (int seed = 1; seed <= kLessOneSeeds; ++seed) {
      mapping::RunConfig c = cli::scenarioConfig(sc, s, static_cast<uint64_t>(seed));
      c.noise = row.noise;
      c.startJitterDeg = row.jitterDeg;
      const report::RunResult r = cli::runOnce(suite.site(sc), c);
      ++t.runs;
      t.detected += r.detectedPct;
      t.worstDetected = std::min(t.worstDetected, r.detectedPct);
      t.unsafeFree += r.unsafeFree;
      t.lost += r.lost > 0.5 ? 1 : 0;
      progress.tick();
    }
  }
  return t;
}

}  // namespace

void lessOneTable(const RealismWorlds& w) {
  const std::vector<LessOne> list = lessOneRows();
  const size_t total = list.size() * 2 * w.suite20.scenarios.size() * kLessOneSeeds;
  std::vector<Tally> measured(list.size() * 2);
  {
    cli::ProgressLine progress(std::cerr, cli::stderrIsTerminal(), progressLabel("realism", "less one fact at a time"),
                               total);
    for (size_t i = 0; i < list.size(); ++i)
      for (size_t k = 0; k < 2; ++k)
        measured[2 * i + k] = runRow(w.suite20, list[i], cli::parseStrategy(mapping::strategyNames()[k]), progress);
  }
  std::cout << "\nrealism 3: less one fact at a time: the brick in the 18 layouts at 20 cm under `nxt`, set down up "
            << "to " << kJitterDeg << " deg off square\nand squared by its sweep (the acceptance's brick rooms), seeds "
            << "1-" << kLessOneSeeds << ", with one measured fact of `nxt` taken away; each row\nagainst the base "
            << "row (difference in brackets). What a fact costs the robot as it is. Lost: runs lost of runs.\n\n";
  std::vector<std::vector<std::string>> rows;
  for (size_t i = 0; i < list.size(); ++i) {
    for (size_t k = 0; k < 2; ++k) {
      const Tally& t = measured[2 * i + k];
      const Tally& b = measured[k];
      const bool isBase = i == 0;
      rows.push_back({list[i].name, mapping::strategyNames()[k],
                      withDelta(t.mean(t.detected), b.mean(b.detected), 1, isBase),
                      withDelta(t.worstDetected, b.worstDetected, 1, isBase),
                      withDelta(t.mean(t.unsafeFree), b.mean(b.unsafeFree), 1, isBase),
                      std::to_string(t.lost) + "/" + std::to_string(t.runs) +
                          (isBase ? "" : " (" + formatDelta(t.lost - b.lost, 0) + ")"),
                      isBase ? "base" : "measured"});
    }
  }
  printColumns({"less", "strategy", "detected %", "worst %", "unsafe free", "lost", "result"}, rows);
}

}  // namespace nxtmap::bench
