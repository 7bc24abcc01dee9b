// PlanBench: the path-search section of `make bench`.
//  1. Every problem of the five Moving AI scenario files (worlds/movingai), astar, jps and jps+, checked
//     against the published optimum; median time per problem.
//  2. PathFinding.js (npm `pathfinding`, AStarFinder, OnlyWhenNoObstacles, octile) on an evenly spread sample
//     of each file, run in the same bench run through scripts/peer (installed locally into build/peer);
//     median time per problem side by side with ours on the same sample, at equal lengths.
//  3. jps and jps+ against astar on the 512x512 maps.
//  4. The published search on the 18 Appendix A rooms: nodes visited against solution depth, next to the
//     published table, and how far its paths are from the optimum.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "host/mapio/MapFiles.hpp"
#include "host/plan/DijkstraPlanner.hpp"
#include "host/plan/JumpTable.hpp"
#include "host/plan/MovingAiScenario.hpp"
#include "host/plan/ScenarioCheck.hpp"
#include "host/plan/SeedSearch.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::bench {
namespace {
namespace fs = std::filesystem;
using report::formatNumber;

constexpr double kPeerSpeedupTarget = 10.0;  // ours >= 10x faster than PathFinding.js
constexpr double kJpsSpeedupTarget = 3.0;    // jps >= 3x faster than astar on 512x512 maps
constexpr size_t kPeerSample = 40;           // problems per map given to the peer
constexpr int kSeedGoalsPerRoom = 6;
constexpr uint64_t kPublishedMaxNodes = 950;  // Appendix A: depth 8-29 -> 35-950 nodes

const char* kMaps[] = {"dao/arena2.map", "maze/maze512-1-0.map", "room/8room_000.map", "random/random512-10-0.map",
                       "street/Berlin_0_512.map"};

// Appendix A, "Time complexity of the path finding algorithm": depth -> number of nodes (c = 4, branch 5).
const std::array<std::pair<int, int>, 7> kPublished = {
    {{21, 95}, {10, 45}, {8, 35}, {16, 75}, {17, 260}, {29, 950}, {20, 290}}};

// worlds/<sub> in the working directory, else in the source tree this file was compiled from.
fs::path worldsDir(const std::string& sub) {
  std::error_code ec;
  const fs::path local = fs::path("worlds") / sub;
  if (fs::exists(local, ec)) return local;
  return fs::path(__FILE__).parent_path().parent_path().parent_path() / "worlds" / sub;
}

fs::path sourceDir() { return fs::path(__FILE__).parent_path().parent_path().parent_path(); }

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream in(path);
  for (std::string dir; std::getline(in, dir, ':');) {
    std::error_code ec;
    if (!dir.empty() && fs::exists(fs::path(dir) / program, ec)) return true;
  }
  return false;
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs a shell command, returns its stdout; exit status in `status`.
std::string capture(const std::string& command, int& status) {
  std::string out;
  FILE* p = ::popen(command.c_str(), "r");
  if (!p) {
    status = -1;
    return out;
  }
  char buf[4096];
  size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  status = ::pclose(p);
  return out;
}

// Installs the peer into peerDir (npm, locally) when missing. Returns "" when ready, else why not.
std::string preparePeer(const fs::path& peerDir) {
  if (!onPath("node") || !onPath("npm")) {
    return "npm/node not available on PATH (install the Debian packages nodejs and npm: make deps)";
  }
  std::error_code ec;
  fs::create_directories(peerDir, ec);
  const fs::path script = sourceDir() / "scripts" / "peer";
  fs::copy_file(script / "package.json", peerDir / "package.json", fs::copy_options::overwrite_existing, ec);
  if (ec) return "cannot copy scripts/peer/package.json into " + peerDir.string() + " (" + ec.message() + ")";
  if (fs::exists(peerDir / "node_modules" / "pathfinding" / "package.json", ec)) return "";
  std::cerr << "[plan] npm install pathfinding into " << peerDir.string() << " ...\n";
  int status = 0;
  const std::string log =
      capture("cd " + quote(peerDir.string()) + " && npm install --no-audit --no-fund --loglevel=error 2>&1", status);
  if (status != 0 || !fs::exists(peerDir / "node_modules" / "pathfinding" / "package.json", ec)) {
    std::string firstLine = log.substr(0, log.find('\n'));
    return "npm install failed in " + peerDir.string() + (firstLine.empty() ? "" : ": " + firstLine);
  }
  return "";
}

struct PeerRun {
  std::vector<double> micros;   // per sample problem
  std::vector<double> lengths;  // -1 = no path
  std::string error;
};

PeerRun runPeer(const fs::path& peerDir, const fs::path& map, const std::vector<plan::ScenarioProblem>& problems,
                const std::vector<size_t>& sample) {
  PeerRun run;
  const fs::path list = peerDir / (map.stem().string() + ".problems.tsv");
  {
    std::ofstream out(list);
    for (size_t i : sample) {
      const plan::ScenarioProblem& p = problems[i];
      out << i << '\t' << p.start.col << '\t' << p.start.row << '\t' << p.goal.col << '\t' << p.goal.row << '\n';
    }
  }
  const fs::path script = sourceDir() / "scripts" / "peer" / "pathfinding-peer.js";
  int status = 0;
  const std::string out = capture("node " + quote(script.string()) + " --modules " + quote(peerDir.string()) + " " +
                                      quote(map.string()) + " " + quote(list.string()),
                                  status);
  std::istringstream in(out);
  std::map<size_t, std::pair<double, double>> byIndex;
  size_t index = 0;
  double length = 0, micros = 0;
  while (in >> index >> length >> micros) byIndex[index] = {length, micros};
  if (status != 0 || byIndex.size() != sample.size()) {
    run.error = "the peer failed on " + map.filename().string() + " (exit " + std::to_string(status) + ")";
    return run;
  }
  for (size_t i : sample) {
    run.lengths.push_back(byIndex[i].first);
    run.micros.push_back(byIndex[i].second);
  }
  return run;
}

class Rows {
 public:
  void add(const std::string& measure, const std::string& what, const std::string& measured, const std::string& target,
           const std::string& result) {
    rows_.push_back({measure, what, measured, target, result});
    if (result == "PASS") ++pass_;
    if (result == "PASS" || result == "MISS") ++targets_;
  }
  void print() const {
    const std::vector<std::string> head = {"measure", "map / algorithm", "measured", "target", "result"};
    std::vector<size_t> w(head.size());
    for (size_t i = 0; i < head.size(); ++i) w[i] = head[i].size();
    for (const auto& r : rows_)
      for (size_t i = 0; i < r.size(); ++i) w[i] = std::max(w[i], r[i].size());
    auto line = [&](const std::vector<std::string>& r) {
      std::string s;
      for (size_t i = 0; i < r.size(); ++i) s += r[i] + std::string(w[i] - r[i].size() + 2, ' ');
      while (!s.empty() && s.back() == ' ') s.pop_back();
      std::cout << s << '\n';
    };
    line(head);
    size_t total = 0;
    for (size_t x : w) total += x + 2;
    std::cout << std::string(total - 2, '-') << '\n';
    for (const auto& r : rows_) line(r);
    std::cout << std::string(total - 2, '-') << '\n'
              << "path search targets met: " << pass_ << " of " << targets_ << '\n';
  }

 private:
  std::vector<std::vector<std::string>> rows_;
  int pass_ = 0, targets_ = 0;
};

const char* verdict(bool ok) { return ok ? "PASS" : "MISS"; }

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

void seedSection(Rows& rows) {
  const fs::path dir = worldsDir("seed-appendix-a");
  const report::ScenarioLoad load = report::loadScenarios((dir / "scenarios.tsv").string());
  if (!load.error.empty()) {
    std::cout << "published search: " << load.error << "\n";
    return;
  }
  struct Sample {
    int depth;
    uint64_t nodes;
    double length, optimal;
  };
  std::vector<Sample> samples;
  plan::SeedSearch seed;
  for (size_t k = 0; k < load.scenarios.size(); ++k) {
    const report::Scenario& s = load.scenarios[k];
    const mapio::MapLoad m = mapio::loadMap(s.mapPath);
    if (!m.map) {
      std::cout << "published search: " << m.error << "\n";
      return;
    }
    const plan::Traversability grid(*m.map);
    const plan::MapCell from{s.startCol, s.startRow};
    const std::vector<double> dist = plan::distancesFrom(grid, from);
    std::vector<plan::MapCell> reachable;
    for (int r = 0; r < grid.height(); ++r)
      for (int c = 0; c < grid.width(); ++c)
        if (std::isfinite(dist[grid.index({c, r})]) && !(plan::MapCell{c, r} == from)) reachable.push_back({c, r});
    std::mt19937 rng(static_cast<uint32_t>(1000 + k));
    std::uniform_int_distribution<size_t> pick(0, reachable.size() - 1);
    for (int g = 0; g < kSeedGoalsPerRoom && !reachable.empty(); ++g) {
      const plan::MapCell to = reachable[pick(rng)];
      const plan::PlanResult r = seed.plan(grid, from, to);
      if (!r.found()) continue;
      samples.push_back({static_cast<int>(r.path.size()) - 1, r.nodesExpanded, r.length, dist[grid.index(to)]});
    }
  }
  std::sort(samples.begin(), samples.end(), [](const Sample& a, const Sample& b) { return a.depth < b.depth; });

  std::cout << "\nPublished search (c = 4, tolerance 3, branch 5 then 8) on the " << load.scenarios.size()
            << " Appendix A rooms, " << kSeedGoalsPerRoom << " random reachable goals from each run's start:\n"
            << "  depth band   problems  nodes visited (min / median / max)   length / optimum (mean / max)"
               "   published (depth -> nodes)\n";
  const int bands[][2] = {{1, 7}, {8, 12}, {13, 17}, {18, 22}, {23, 29}, {30, 1000}};
  uint64_t maxNodesInRange = 0;
  double sumRatio = 0, maxRatio = 1;
  size_t inRange = 0;
  for (const auto& band : bands) {
    std::vector<double> nodes;
    double ratioSum = 0, ratioMax = 1;
    for (const Sample& s : samples) {
      if (s.depth < band[0] || s.depth > band[1]) continue;
      nodes.push_back(static_cast<double>(s.nodes));
      const double ratio = s.optimal > 0 ? s.length / s.optimal : 1.0;
      ratioSum += ratio;
      ratioMax = std::max(ratioMax, ratio);
    }
    std::string published;
    for (const auto& [d, n] : kPublished) {
      if (d >= band[0] && d <= band[1])
        published += (published.empty() ? "" : ", ") + std::to_string(d) + " -> " + std::to_string(n);
    }
    if (nodes.empty() && published.empty()) continue;
    char line[256];
    const std::string bandText =
        band[1] >= 1000 ? std::to_string(band[0]) + "+" : std::to_string(band[0]) + "-" + std::to_string(band[1]);
    if (nodes.empty()) {
      std::snprintf(line, sizeof line, "  %-11s  %8d  %-36s  %-29s  %s\n", bandText.c_str(), 0, "-", "-",
                    published.c_str());
    } else {
      const std::string n = formatNumber(*std::min_element(nodes.begin(), nodes.end()), 0) + " / " +
                            formatNumber(plan::median(nodes), 0) + " / " +
                            formatNumber(*std::max_element(nodes.begin(), nodes.end()), 0);
      const std::string l =
          formatNumber(ratioSum / static_cast<double>(nodes.size()), 3) + " / " + formatNumber(ratioMax, 3);
      std::snprintf(line, sizeof line, "  %-11s  %8zu  %-36s  %-29s  %s\n", bandText.c_str(), nodes.size(), n.c_str(),
                    l.c_str(), published.c_str());
    }
    std::cout << line;
  }
  for (const Sample& s : samples) {
    const double ratio = s.optimal > 0 ? s.length / s.optimal : 1.0;
    sumRatio += ratio;
    maxRatio = std::max(maxRatio, ratio);
    if (s.depth >= 8 && s.depth <= 29) {
      maxNodesInRange = std::max(maxNodesInRange, s.nodes);
      ++inRange;
    }
  }
  rows.add("published search: max nodes visited, depth 8-29", std::to_string(inRange) + " problems, 18 rooms",
           std::to_string(maxNodesInRange), "<= " + std::to_string(kPublishedMaxNodes) + " (published max)",
           verdict(inRange > 0 && maxNodesInRange <= kPublishedMaxNodes));
  rows.add("published search: path length / optimum", std::to_string(samples.size()) + " problems",
           "mean " + formatNumber(samples.empty() ? 0 : sumRatio / static_cast<double>(samples.size()), 3) + ", max " +
               formatNumber(maxRatio, 3),
           "(info: not an optimal search)", "");
}

}  // namespace

int runPlanBench() {
  std::cout << "\n== Path search (host/plan) ==\n";
  const fs::path peerDir = fs::path(std::getenv("NXTMAP_PEER_DIR") ? std::getenv("NXTMAP_PEER_DIR") : "build/peer");
  const std::string peerProblem = preparePeer(peerDir);
  if (!peerProblem.empty()) std::cout << "PathFinding.js peer: NOT RUN - " << peerProblem << "\n";

  Rows rows;
  std::vector<MapRun> runs;
  for (const char* rel : kMaps) {
    const fs::path mapPath = worldsDir("movingai") / rel;
    MapRun run;
    run.name = mapPath.stem().string();
    const mapio::MapLoad m = mapio::loadMap(mapPath.string());
    const plan::ScenarioLoad scen = plan::loadScenario(mapPath.string() + ".scen");
    if (!m.map || !scen.problems) {
      std::cout << run.name << ": " << (m.map ? scen.error : m.error) << "\n";
      rows.add("optimum reproduced", run.name, "cannot load", "all", "MISS");
      continue;
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
    for (size_t a = 0; a < 3; ++a) {
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
    if (peerProblem.empty()) {
      std::cerr << "[plan] " << run.name << ": PathFinding.js on " << sample.size() << " problems...\n";
      const PeerRun peer = runPeer(peerDir, mapPath, problems, sample);
      run.peerError = peer.error;
      if (peer.error.empty()) {
        run.samplePeer = plan::median(peer.micros);
        for (size_t k = 0; k < sample.size(); ++k) {
          if (std::fabs(peer.lengths[k] - problems[sample[k]].optimal) <= plan::kScenarioTolerance) ++run.peerEqual;
        }
      }
    } else {
      run.peerError = "not run";
    }
    runs.push_back(run);
  }

  auto ratio = [](double slow, double fast) { return slow / std::max(fast, 1e-3); };
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
  seedSection(rows);
  std::cout << "\n";
  rows.print();
  return 0;
}

}  // namespace nxtmap::bench
