// The realism section of `make bench` (nxtmap-bench realism: this section alone). Information, not targets:
// every row is "measured", nothing passes or fails except that it ran.
//  1. preset x strategy x {published rooms, brick rooms, furnished rooms, HouseExpo houses}
//  2. one factor at a time: `typical` plus one measured fact of `nxt` (RealismFactors.cpp), each row
//     against its base row; a factor that changes no number is flagged, not hidden.
#include "host/bench/RealismBench.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/ExperimentRunner.hpp"
#include "host/report/ExperimentTable.hpp"
#include "host/worlds/SiteFiles.hpp"

namespace nxtmap::bench {
namespace {
namespace fs = std::filesystem;
using report::formatNumber;

constexpr int kRoomSeeds = 5;       // preset table, published and brick rooms
constexpr int kFurnishedSeeds = 5;  // preset table, furnished rooms
constexpr int kHouseSeeds = 3;      // preset table, houses
constexpr int kHouses = 3;          // the first HouseExpo plans by name (the small ones: affordable)

std::vector<fs::path> filesIn(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (e.path().extension() == ext) out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string pad(const std::string& s, size_t w) { return s.size() >= w ? s : s + std::string(w - s.size(), ' '); }

}  // namespace

void RealismWorlds::load() {
  const fs::path root = worldsRoot();
  suite10 = cli::loadSuite((root / "seed-appendix-a").string(), 10);
  suite20 = cli::loadSuite((root / "seed-appendix-a").string(), 20);
  published = RealismSet{"published", *sim::robotByName("published"), {}, kRoomSeeds, false};
  brick = RealismSet{"brick", *sim::robotByName("brick"), {}, kRoomSeeds, false};
  for (const report::Scenario& s : suite10.scenarios)
    published.starts.push_back({&suite10.site(s), s.startCol, s.startRow, {}});
  for (const report::Scenario& s : suite20.scenarios)
    brick.starts.push_back({&suite20.site(s), s.startCol, s.startRow, {}});

  furnished = RealismSet{"furnished", *sim::robotByName("brick"), {}, kFurnishedSeeds, false};
  houses = RealismSet{"houses", *sim::robotByName("published"), {}, kHouseSeeds, true};
  const std::vector<fs::path> rooms = filesIn(root / "rooms", ".yaml");
  std::vector<fs::path> plans = filesIn(root / "houseexpo", ".json");
  if (plans.size() > static_cast<size_t>(kHouses)) plans.resize(static_cast<size_t>(kHouses));
  sites.clear();
  sites.reserve(rooms.size() + plans.size());  // the sets point into `sites`
  auto add = [&](const fs::path& f, RealismSet& set) {
    worlds::SiteLoad l = worlds::loadSite(f.string(), set.robot.cellCm);
    if (!l.site) throw cli::CliError(l.error);
    if (!l.site->start) throw cli::CliError(f.string() + ": no start in the world file");
    sites.push_back(std::move(*l.site));
    set.starts.push_back({&sites.back(), 0, 0, sites.back().start});
  };
  for (const fs::path& f : rooms) add(f, furnished);
  for (const fs::path& f : plans) add(f, houses);
}

std::string formatDelta(double v, int decimals) {
  const std::string n = formatNumber(v, decimals);
  if (n == "0" || n == "-0") return "0";
  return v > 0 ? "+" + n : n;
}

void printColumns(const std::vector<std::string>& head, const std::vector<std::vector<std::string>>& rows) {
  std::vector<size_t> w(head.size());
  for (size_t i = 0; i < head.size(); ++i) w[i] = head[i].size();
  for (const auto& r : rows)
    for (size_t i = 0; i < r.size() && i < w.size(); ++i) w[i] = std::max(w[i], r[i].size());
  auto line = [&](const std::vector<std::string>& r) {
    std::string s;
    for (size_t i = 0; i < r.size() && i < w.size(); ++i) s += pad(r[i], w[i] + 2);
    while (!s.empty() && s.back() == ' ') s.pop_back();
    std::cout << s << '\n';
  };
  line(head);
  size_t total = 0;
  for (size_t x : w) total += x + 2;
  std::cout << std::string(total - 2, '-') << '\n';
  for (const auto& r : rows) {
    if (r.empty())
      std::cout << '\n';
    else
      line(r);
  }
}

std::string withDelta(double v, double base, int decimals, bool isBase) {
  const std::string s = formatNumber(v, decimals);
  return isBase ? s : s + " (" + formatDelta(v - base, decimals) + ")";
}

std::string progressLabel(const std::string& section, const std::string& part) { return section + ": " + part; }

namespace {

// Table 1: every preset, both strategies, every set of worlds; the start square on the cell centre.
void presetTable(const RealismWorlds& w) {
  const std::vector<const RealismSet*> sets = {&w.published, &w.brick, &w.furnished, &w.houses};
  size_t total = 0;
  for (const RealismSet* s : sets) total += s->starts.size() * static_cast<size_t>(s->seeds);
  total *= sim::noiseProfileNames().size() * mapping::strategyNames().size();
  std::cout
      << "\nrealism 1: noise preset x strategy x worlds (information, no targets). Every run set down square on\n"
      << "its start (no jitter, no misalignment: misalignment is a factor of table 2). Detected % of observable\n"
      << "occupied cells in the start frame (mean, worst), wrong and unsafe-free cells (means), lost runs, and the\n"
      << "same map after the best rigid alignment (detected %, wrong cells). Worlds: published = the 18 Appendix-A\n"
      << "runs at 10 cm, published robot, seeds 1-" << kRoomSeeds
      << "; brick = the same layouts at 20 cm cells, brick\n"
      << "robot, seeds 1-" << kRoomSeeds << "; furnished = worlds/rooms (" << w.furnished.starts.size()
      << " rooms), brick robot, seeds 1-" << kFurnishedSeeds << "; houses = " << w.houses.starts.size()
      << " HouseExpo plans (the first by name), published robot, HouseMapper, seeds 1-" << kHouseSeeds
      << "\n(houses: the merged map scored like a room's; lost not known, HouseMapper keeps its belief to itself;\n"
      << "agreement %: the house section's own measure, free and occupied cells of the observable area alike).\n\n";
  std::vector<std::vector<std::string>> rows;
  cli::ProgressLine progress(std::cerr, cli::stderrIsTerminal(), progressLabel("realism", "presets"), total);
  for (const RealismSet* set : sets) {
    for (const std::string& preset : sim::noiseProfileNames()) {
      for (const std::string& name : mapping::strategyNames()) {
        const Tally t = runRealism(*set, presetVariant(preset), cli::parseStrategy(name), [&] { progress.tick(); });
        rows.push_back({set->name, preset, name, std::to_string(t.runs), formatNumber(t.mean(t.detected), 1),
                        formatNumber(t.worstDetected, 1), formatNumber(t.mean(t.wrong), 1),
                        formatNumber(t.mean(t.unsafeFree), 1),
                        t.lostKnown ? std::to_string(t.lost) + "/" + std::to_string(t.runs) : "-",
                        formatNumber(t.mean(t.detectedAligned), 1), formatNumber(t.mean(t.wrongAligned), 1),
                        t.lostKnown ? "-" : formatNumber(t.mean(t.agreement), 1), "measured"});
      }
    }
    rows.push_back({});
  }
  rows.pop_back();
  printColumns({"worlds", "preset", "strategy", "runs", "detected %", "worst %", "wrong", "unsafe free", "lost",
                "aligned %", "wrong aligned", "agreement %", "result"},
               rows);
}

}  // namespace

int runRealismBench() {
  const auto t0 = std::chrono::steady_clock::now();
  RealismWorlds w;
  w.load();
  presetTable(w);
  factorTable(w);
  lessOneTable(w);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "\nrealism section: wall time " << formatNumber(s, 1) << " s (every row ran)\n";
  return 0;
}

int runLessOneBench() {
  const auto t0 = std::chrono::steady_clock::now();
  RealismWorlds w;
  w.load();
  lessOneTable(w);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "\nrealism 3: wall time " << formatNumber(s, 1) << " s (every row ran)\n";
  return 0;
}

}  // namespace nxtmap::bench
