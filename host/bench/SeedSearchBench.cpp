#include "host/bench/SeedSearchBench.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "host/bench/BenchWorlds.hpp"
#include "host/mapio/MapFiles.hpp"
#include "host/plan/DijkstraPlanner.hpp"
#include "host/plan/ScenarioCheck.hpp"
#include "host/plan/SeedSearch.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::bench {
namespace {
using report::formatNumber;

constexpr int kSeedGoalsPerRoom = 6;
constexpr uint64_t kPublishedMaxNodes = 950;  // Appendix A: depth 8-29 -> 35-950 nodes

// Appendix A, "Time complexity of the path finding algorithm": depth -> number of nodes (c = 4, branch 5).
const std::array<std::pair<int, int>, 7> kPublished = {
    {{21, 95}, {10, 45}, {8, 35}, {16, 75}, {17, 260}, {29, 950}, {20, 290}}};

}  // namespace

void addSeedSearchRows(TargetRows& rows) {
  const std::filesystem::path dir = worldsRoot() / "seed-appendix-a";
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

}  // namespace nxtmap::bench
