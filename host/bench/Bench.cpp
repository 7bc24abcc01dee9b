// nxtmap-bench (`make bench`): speed and quality of both strategies on the 18 Appendix-A runs,
// measured against their targets.
//   nxtmap-bench [SCENARIO_DIR]   (default: ./worlds/seed-appendix-a, else the source tree's)
//   nxtmap-bench plan             the path-search section alone (host/bench/PlanBench.cpp)
//   nxtmap-bench house            the house section alone (host/bench/HouseBench.cpp)
//   nxtmap-bench realism          the realism section alone (host/bench/RealismBench.cpp)
//   nxtmap-bench less-one         its table 3 alone: the acceptance's brick less one fact (RealismLessOne.cpp)
//   nxtmap-bench acceptance       the real-room acceptance section alone (host/bench/AcceptanceBench.cpp)
//   nxtmap-bench lego             the LEGO round trip alone (host/bench/LegoRoundTripBench.cpp)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "host/bench/BenchWorlds.hpp"
#include "host/bench/TargetRows.hpp"
#include "host/bench/LinkBench.hpp"
#include "host/bench/AcceptanceBench.hpp"
#include "host/bench/EmuBench.hpp"
#include "host/bench/EmuRoomBench.hpp"
#include "host/bench/LegoRoundTripBench.hpp"
#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/ExperimentRunner.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::bench {
int runPlanBench();     // host/bench/PlanBench.cpp: the path-search section
int runHouseBench();    // host/bench/HouseBench.cpp: the house section
int runRealismBench();  // host/bench/RealismBench.cpp: the realism section
int runLessOneBench();  // host/bench/RealismBench.cpp: its table 3 alone
}  // namespace nxtmap::bench

namespace {
namespace fs = std::filesystem;
using nxtmap::report::formatNumber;

constexpr double kWallTargetS = 2.0;
constexpr double kRatioTarget = 0.5;
constexpr double kNoisyDetectTargetPct = 98.0;
constexpr double kNoisyWrongTargetPct = 1.0;
constexpr int kNoisySeeds = 10;

std::string scenarioDir(int argc, char** argv) {
  if (argc > 1) return argv[1];
  return (nxtmap::bench::worldsRoot() / "seed-appendix-a").string();
}

struct Clean {
  std::string strategy;
  nxtmap::report::ExperimentTable table;
  double wallS = 0;
  double timeRatio = 0, sensorRatio = 0;
  double minDetected = 100, maxWrong = 0;
  bool allComplete = true;
};

struct Noisy {
  double meanDetected = 0, minDetected = 100, meanWrongPct = 0, maxWrongPct = 0;
};

int run(int argc, char** argv) {
  using namespace nxtmap;
  using bench::verdict;
  const std::string dir = scenarioDir(argc, argv);
  const cli::Suite suite = cli::loadSuite(dir);
  const size_t n = suite.scenarios.size();
  std::cout << "nxtmap-bench: " << suite.tsvPath << ", " << n << " runs, 1 m range, initial heading N\n"
            << "published medians (thesis, Chapter 5): " << formatNumber(report::kPublishedMedianTimeUnits)
            << " time units, " << formatNumber(report::kPublishedMedianSensorReads) << " sensor reads\n\n"
            << std::flush;

  std::vector<Clean> clean;
  std::vector<Noisy> noisy;
  for (const std::string& name : mapping::strategyNames()) {
    const mapping::Strategy s = cli::parseStrategy(name);
    Clean c;
    c.strategy = name;
    const auto t0 = std::chrono::steady_clock::now();
    c.table = cli::runSuite(suite, s, "none", 1);
    const auto t1 = std::chrono::steady_clock::now();
    c.wallS = std::chrono::duration<double>(t1 - t0).count();
    c.timeRatio = c.table.medianTimeUnits() / report::kPublishedMedianTimeUnits;
    c.sensorRatio = c.table.medianSensorReads() / report::kPublishedMedianSensorReads;
    for (const auto& r : c.table.rows) {
      c.minDetected = std::min(c.minDetected, r.mean.detectedPct);
      c.maxWrong = std::max(c.maxWrong, r.mean.wrongCells);
      c.allComplete = c.allComplete && r.mean.complete;
    }
    clean.push_back(std::move(c));

    std::cerr << "[" << name << "] typical noise, " << kNoisySeeds << " seeds x " << n << " runs...\n";
    const report::ExperimentTable t = cli::runSuite(suite, s, "typical", kNoisySeeds);
    Noisy z;
    double runs = 0;
    for (const auto& r : t.rows) {
      for (const auto& one : r.perSeed) {
        const double wrongPct = one.roomCells > 0 ? 100.0 * one.wrongCells / one.roomCells : 0.0;
        z.meanDetected += one.detectedPct;
        z.minDetected = std::min(z.minDetected, one.detectedPct);
        z.meanWrongPct += wrongPct;
        z.maxWrongPct = std::max(z.maxWrongPct, wrongPct);
        runs += 1;
      }
    }
    if (runs > 0) {
      z.meanDetected /= runs;
      z.meanWrongPct /= runs;
    }
    noisy.push_back(z);
  }

  nxtmap::bench::TargetRows table("strategy", "targets met");
  auto pct = [](double v) { return formatNumber(v, 2) + " %"; };
  for (const Clean& c : clean) {
    table.add("median time units (no noise)", c.strategy,
              formatNumber(c.table.medianTimeUnits(), 1) + " = " + formatNumber(c.timeRatio, 2) + "x",
              "published " + formatNumber(report::kPublishedMedianTimeUnits), "");
  }
  for (const Clean& c : clean) {
    table.add("median sensor requests (no noise)", c.strategy,
              formatNumber(c.table.medianSensorReads(), 1) + " = " + formatNumber(c.sensorRatio, 2) + "x",
              "published " + formatNumber(report::kPublishedMedianSensorReads), "");
  }
  for (const Clean& c : clean) {
    table.add("detected % of observable, every run", c.strategy, "min " + pct(c.minDetected), "100 %",
              verdict(c.minDetected >= 100.0 - 1e-9));
  }
  for (const Clean& c : clean) {
    table.add("wrong cells, every run", c.strategy, "max " + formatNumber(c.maxWrong), "0", verdict(c.maxWrong == 0.0));
  }
  // The better strategy: the smaller of the two ratios' maximum, among those detecting 100 %.
  const Clean* best = nullptr;
  for (const Clean& c : clean) {
    const bool full = c.minDetected >= 100.0 - 1e-9 && c.maxWrong == 0.0;
    if (!full) continue;
    if (!best || std::max(c.timeRatio, c.sensorRatio) < std::max(best->timeRatio, best->sensorRatio)) best = &c;
  }
  table.add("better strategy: time and sensors vs published", best ? best->strategy : "none",
            best ? formatNumber(best->timeRatio, 2) + "x, " + formatNumber(best->sensorRatio, 2) + "x" : "-",
            "both <= " + formatNumber(kRatioTarget) + "x, 100 %",
            verdict(best && best->timeRatio <= kRatioTarget && best->sensorRatio <= kRatioTarget));
  table.rule();
  for (const Clean& c : clean) {
    table.add("wall time, " + std::to_string(n) + "-run suite, 1 core", c.strategy, formatNumber(c.wallS, 3) + " s",
              "< " + formatNumber(kWallTargetS) + " s", verdict(c.wallS < kWallTargetS));
  }
  table.rule();
  const std::string noisyLabel = "typical noise, " + std::to_string(kNoisySeeds) + " seeds: ";
  for (size_t i = 0; i < clean.size(); ++i) {
    table.add(noisyLabel + "mean detected %", clean[i].strategy, pct(noisy[i].meanDetected),
              ">= " + formatNumber(kNoisyDetectTargetPct) + " %",
              verdict(noisy[i].meanDetected >= kNoisyDetectTargetPct));
    table.add(noisyLabel + "min detected %", clean[i].strategy, pct(noisy[i].minDetected), "(info)", "");
  }
  for (size_t i = 0; i < clean.size(); ++i) {
    table.add(noisyLabel + "mean wrong cells", clean[i].strategy, pct(noisy[i].meanWrongPct) + " of room",
              "<= " + formatNumber(kNoisyWrongTargetPct) + " %",
              verdict(noisy[i].meanWrongPct <= kNoisyWrongTargetPct));
    table.add(noisyLabel + "max wrong cells", clean[i].strategy, pct(noisy[i].maxWrongPct) + " of room", "(info)", "");
  }
  table.print();
  bench::printLinkBench(dir + "/occupancy-120.map", 1, 20);
  nxtmap::bench::runEmuBench(dir);            // the emulated brick's budgets on the real firmware
  nxtmap::bench::runEmuRoomBench(dir);        // the flash image's map under nxt beside the host's
  nxtmap::bench::runLegoRoundTripBench(dir);  // a PC tool's wait for the brick, idle and driving
  const int rc = nxtmap::bench::runPlanBench();
  if (rc != 0) return rc;
  const int house = nxtmap::bench::runHouseBench();
  if (house != 0) return house;
  const int acceptance = nxtmap::bench::runAcceptanceBench();
  return acceptance != 0 ? acceptance : nxtmap::bench::runRealismBench();
}
}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc > 1 && std::string(argv[1]) == "plan") return nxtmap::bench::runPlanBench();        // that section alone
    if (argc > 1 && std::string(argv[1]) == "house") return nxtmap::bench::runHouseBench();      // that section alone
    if (argc > 1 && std::string(argv[1]) == "realism") return nxtmap::bench::runRealismBench();  // that section alone
    if (argc > 1 && std::string(argv[1]) == "less-one") return nxtmap::bench::runLessOneBench();
    if (argc > 1 && std::string(argv[1]) == "acceptance") return nxtmap::bench::runAcceptanceBench();
    if (argc > 1 && std::string(argv[1]) == "emu") return nxtmap::bench::runEmuBench(scenarioDir(1, argv));
    if (argc > 1 && std::string(argv[1]) == "emu-room") return nxtmap::bench::runEmuRoomBench(scenarioDir(1, argv));
    if (argc > 1 && std::string(argv[1]) == "lego") return nxtmap::bench::runLegoRoundTripBench(scenarioDir(1, argv));
    if (argc > 1 && std::string(argv[1]) == "link") {  // that section alone
      nxtmap::bench::printLinkBench(scenarioDir(1, argv) + "/occupancy-120.map", 1, 20);
      return 0;
    }
    return run(argc, argv);
  } catch (const nxtmap::cli::CliError& e) {
    nxtmap::cli::printError(std::string("bench: ") + e.what());
    return nxtmap::cli::kExitUsage;
  }
}
