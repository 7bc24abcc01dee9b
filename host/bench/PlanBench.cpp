// PlanBench: the path-search section of `make bench`.
//  1. Every problem of the five Moving AI scenario files (worlds/movingai), astar, jps and jps+, checked
//     against the published optimum; median time per problem.
//  2. PathFinding.js (npm `pathfinding`, AStarFinder, OnlyWhenNoObstacles, octile) on an evenly spread sample
//     of each file, run in the same bench run through scripts/peer (PathFindingPeer, installed into build/peer);
//     median time per problem side by side with ours on the same sample, at equal lengths.
//  3. jps and jps+ against astar on the 512x512 maps.
//  4. The published search on the 18 Appendix A rooms (SeedSearchBench).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "host/bench/BenchWorlds.hpp"
#include "host/bench/PathFindingPeer.hpp"
#include "host/bench/SeedSearchBench.hpp"
#include "host/bench/TargetRows.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/plan/JumpTable.hpp"
#include "host/plan/MovingAiScenario.hpp"
#include "host/plan/ScenarioCheck.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::bench {
namespace {
namespace fs = std::filesystem;
using report::formatNumber;

constexpr double kPeerSpeedupTarget = 10.0;  // ours >= 10x faster than PathFinding.js
constexpr double kJpsSpeedupTarget = 3.0;    // jps >= 3x faster than astar on 512x512 maps
constexpr size_t kPeerSample = 40;           // problems per map given to the peer

const char* kMaps[] = {"dao/arena2.map", "maze/maze512-1-0.map", "room/8room_000.map", "random/random512-10-0.map",
                       "street/Berlin_0_512.map"};

std::string ms(double micros) { return formatNumber(micros / 1000.0, 3) + " ms"; }

// The optimal planners timed on every problem: astar, jps, jps+.
constexpr plan::Algorithm kTimed[] = {plan::Algorithm::AStar, plan::Algorithm::Jps, plan::Algorithm::JpsPlus};
constexpr size_t kA = 0, kJ = 1, kJP = 2;

struct MapRun {
  std::string name;
  int width = 0, height = 0;
  size_t problems = 0;
  std::array<size_t, 3> matched{};       // per timed algorithm
  std::array<double, 3> median{};        // all problems, microseconds
  std::array<double, 3> sampleMedian{};  // the peer's sample, microseconds
  double tableMs = 0;                    // jps+ jump table build, once per map
  double samplePeer = 0;
  size_t peerEqual = 0, peerSample = 0;  // peer lengths equal to the optimum
  std::string peerError;
};

// One algorithm (kTimed[a]) on every problem: how many match the optimum, the median time over all (jps+'s first,
// which builds its table, left out) and over the peer's sample.
void timeAlgorithm(MapRun& run, size_t a, const plan::Traversability& grid,
                   const std::vector<plan::ScenarioProblem>& problems, const std::vector<size_t>& sample) {
  std::cerr << "[plan] " << run.name << ": " << problems.size() << " problems, " << plan::algorithmName(kTimed[a])
            << "...\n";
  auto planner = plan::makePlanner(kTimed[a]);
  const auto out = plan::runProblems(*planner, grid, problems);  // jps+ builds its table on the first one
  std::vector<double> t, st;
  for (size_t i = 0; i < problems.size(); ++i) {
    run.matched[a] += out[i].matches ? 1 : 0;
    if (!(kTimed[a] == plan::Algorithm::JpsPlus && i == 0)) t.push_back(out[i].micros);
  }
  for (size_t i : sample) st.push_back(out[i].micros);
  run.median[a] = plan::median(t);
  run.sampleMedian[a] = plan::median(st);
}

// Every problem of one Moving AI file timed with astar, jps and jps+ and checked against its optimum, and the peer
// on an evenly spread sample (peerProblem non-empty: not run, why). Nullopt (a MISS row added) when it cannot load.
std::optional<MapRun> timeMap(const fs::path& mapPath, const fs::path& peerDir, const std::string& peerProblem,
                              TargetRows& rows) {
  MapRun run;
  run.name = mapPath.stem().string();
  const mapio::MapLoad m = mapio::loadMap(mapPath.string());
  const plan::ScenarioLoad scen = plan::loadScenario(mapPath.string() + ".scen");
  if (!m.map || !scen.problems) {
    std::cout << run.name << ": " << (m.map ? scen.error : m.error) << "\n";
    rows.add("optimum reproduced", run.name, "cannot load", "all", "MISS");
    return std::nullopt;
  }
  const std::vector<plan::ScenarioProblem>& problems = *scen.problems;
  run.width = m.map->width();
  run.height = m.map->height();
  run.problems = problems.size();
  const plan::Traversability grid(*m.map);
  {
    const auto t0 = std::chrono::steady_clock::now();
    const plan::JumpTable table(grid);
    run.tableMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  }
  std::vector<size_t> sample;
  const size_t step = std::max<size_t>(1, problems.size() / kPeerSample);
  for (size_t i = step / 2; i < problems.size() && sample.size() < kPeerSample; i += step) sample.push_back(i);
  run.peerSample = sample.size();
  for (size_t a = 0; a < 3; ++a) timeAlgorithm(run, a, grid, problems, sample);
  if (!peerProblem.empty()) {
    run.peerError = "not run";
    return run;
  }
  std::cerr << "[plan] " << run.name << ": PathFinding.js on " << sample.size() << " problems...\n";
  const PeerRun peer = runPeer(peerDir, mapPath, problems, sample);
  run.peerError = peer.error;
  if (!peer.error.empty()) return run;
  run.samplePeer = plan::median(peer.micros);
  for (size_t k = 0; k < sample.size(); ++k) {
    if (std::fabs(peer.lengths[k] - problems[sample[k]].optimal) <= plan::kScenarioTolerance) ++run.peerEqual;
  }
  return run;
}

double ratio(double slow, double fast) { return slow / std::max(fast, 1e-3); }

void printTimes(const std::vector<MapRun>& runs) {
  std::cout << "\nMoving AI problems, every one (time = the search alone; the map's traversability is built once per "
               "map, and jps+ builds its jump table once per map, outside the medians):\n"
            << "  map              size      problems  optimal astar / jps / jps+  median astar    jps         jps+"
               "        jps+ table  jps vs astar  jps+ vs astar\n";
  for (const MapRun& r : runs) {
    char line[320];
    const std::string opt =
        std::to_string(r.matched[kA]) + " / " + std::to_string(r.matched[kJ]) + " / " + std::to_string(r.matched[kJP]);
    std::snprintf(line, sizeof line, "  %-15s  %-8s  %8zu  %-26s  %-14s  %-10s  %-10s  %-10s  %11sx  %12sx\n",
                  r.name.c_str(), (std::to_string(r.width) + "x" + std::to_string(r.height)).c_str(), r.problems,
                  opt.c_str(), ms(r.median[kA]).c_str(), ms(r.median[kJ]).c_str(), ms(r.median[kJP]).c_str(),
                  (formatNumber(r.tableMs, 1) + " ms").c_str(),
                  formatNumber(ratio(r.median[kA], r.median[kJ]), 1).c_str(),
                  formatNumber(ratio(r.median[kA], r.median[kJP]), 1).c_str());
    std::cout << line;
  }
}

void printPeer(const std::vector<MapRun>& runs) {
  std::cout << "\nSide by side with PathFinding.js 0.4.18 (AStarFinder, OnlyWhenNoObstacles, octile; node, findPath "
               "alone, the grid cloned outside the clock) on an evenly spread sample of each file:\n"
            << "  map              sample  peer = optimum  peer median  astar       jps         jps+        "
               "astar vs peer  jps vs peer  jps+ vs peer\n";
  for (const MapRun& r : runs) {
    char line[320];
    if (!r.peerError.empty()) {
      std::snprintf(line, sizeof line, "  %-15s  %6zu  %s\n", r.name.c_str(), r.peerSample, r.peerError.c_str());
    } else {
      std::snprintf(line, sizeof line, "  %-15s  %6zu  %14s  %11s  %-10s  %-10s  %-10s  %12sx  %10sx  %11sx\n",
                    r.name.c_str(), r.peerSample,
                    (std::to_string(r.peerEqual) + "/" + std::to_string(r.peerSample)).c_str(),
                    ms(r.samplePeer).c_str(), ms(r.sampleMedian[kA]).c_str(), ms(r.sampleMedian[kJ]).c_str(),
                    ms(r.sampleMedian[kJP]).c_str(), formatNumber(ratio(r.samplePeer, r.sampleMedian[kA]), 1).c_str(),
                    formatNumber(ratio(r.samplePeer, r.sampleMedian[kJ]), 1).c_str(),
                    formatNumber(ratio(r.samplePeer, r.sampleMedian[kJP]), 1).c_str());
    }
    std::cout << line;
  }
}

void addTargetRows(TargetRows& rows, const std::vector<MapRun>& runs) {
  for (const MapRun& r : runs) {
    const bool all = r.matched[kA] == r.problems && r.matched[kJ] == r.problems && r.matched[kJP] == r.problems;
    rows.add("astar, jps, jps+ reproduce the published optimum", r.name,
             std::to_string(r.matched[kA]) + ", " + std::to_string(r.matched[kJ]) + ", " +
                 std::to_string(r.matched[kJP]) + " of " + std::to_string(r.problems),
             "all (within 1e-3)", verdict(all));
  }
  for (size_t a : {kJ, kA, kJP}) {
    for (const MapRun& r : runs) {
      const std::string who = r.name + " / " + plan::algorithmName(kTimed[a]);
      if (!r.peerError.empty()) {
        rows.add("median time vs PathFinding.js, equal lengths", who, "peer " + r.peerError,
                 ">= " + formatNumber(kPeerSpeedupTarget, 0) + "x faster", "MISS");
        continue;
      }
      const double speedup = ratio(r.samplePeer, r.sampleMedian[a]);
      // The target is held by jps, the planner for large maps; astar and jps+ are shown beside it.
      const bool held = a == kJ;
      rows.add("median time vs PathFinding.js, equal lengths", who, formatNumber(speedup, 1) + "x",
               held ? ">= " + formatNumber(kPeerSpeedupTarget, 0) + "x faster" : "(info)",
               held
                   ? verdict(speedup >= kPeerSpeedupTarget && r.peerEqual == r.peerSample && r.matched[a] == r.problems)
                   : "");
    }
  }
  for (size_t a : {kJ, kJP}) {
    for (const MapRun& r : runs) {
      if (r.width != 512 || r.height != 512) continue;
      rows.add(std::string(plan::algorithmName(kTimed[a])) + " vs astar, median time per problem", r.name,
               formatNumber(ratio(r.median[kA], r.median[a]), 1) + "x",
               ">= " + formatNumber(kJpsSpeedupTarget, 0) + "x faster",
               verdict(ratio(r.median[kA], r.median[a]) >= kJpsSpeedupTarget));
    }
  }
}

}  // namespace

int runPlanBench() {
  std::cout << "\n== Path search (host/plan) ==\n";
  const fs::path peerDir = fs::path(std::getenv("NXTMAP_PEER_DIR") ? std::getenv("NXTMAP_PEER_DIR") : "build/peer");
  const std::string peerProblem = preparePeer(peerDir);
  if (!peerProblem.empty()) std::cout << "PathFinding.js peer: NOT RUN - " << peerProblem << "\n";
  TargetRows rows("map / algorithm", "path search targets met");
  std::vector<MapRun> runs;
  for (const char* rel : kMaps) {
    if (std::optional<MapRun> run = timeMap(worldsRoot() / "movingai" / rel, peerDir, peerProblem, rows))
      runs.push_back(*run);
  }
  printTimes(runs);
  printPeer(runs);
  addTargetRows(rows, runs);
  addSeedSearchRows(rows);
  std::cout << "\n";
  rows.print();
  return 0;
}

}  // namespace nxtmap::bench
