#include "host/bench/AcceptanceBench.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "host/bench/RealismBench.hpp"
#include "host/cli/Args.hpp"
#include "host/cli/Errors.hpp"
#include "host/cli/ExperimentRunner.hpp"
#include "host/house/BestFramesScore.hpp"
#include "host/house/HouseExpoPlan.hpp"
#include "host/house/HouseMapper.hpp"
#include "host/house/HouseScore.hpp"
#include "host/worlds/SiteFiles.hpp"

namespace nxtmap::bench {
namespace {
namespace fs = std::filesystem;
using report::formatNumber;

constexpr int kRoomSeeds = 10;  // brick rooms: seeds 1-10 per layout and strategy (the issue's)
// Brick rooms' seeds: kRoomSeeds, or NXTMAP_ACCEPTANCE_ROOM_SEEDS (1-1000) to resolve smaller differences (ten
// seeds' means move by about 1.3 points with any change to the runs' courses).
int roomSeeds() {
  const char* env = std::getenv("NXTMAP_ACCEPTANCE_ROOM_SEEDS");
  return env ? std::clamp(std::atoi(env), 1, 1000) : kRoomSeeds;
}
constexpr int kHouseSeeds = 20;  // houses: seeds 1-20 per plan
constexpr double kJitterDeg = 10.0;

// Brick rooms under one preset and strategy, summed over every layout and seed.
struct RoomFigures {
  double detected = 0, worst = 100, wrongPct = 0, unsafePct = 0;
  double headingOffPct = 0, positionOffPct = 0;  // means over the runs (mapping::PoseErrorShare)
  report::ExperimentTable::Squaring squaring;    // how square the start's sweep left the runs that found walls
  int runs = 0, lost = 0;
};

// afterFirstOuting: each robot first maps another layout with nothing stored (SuiteSettings::afterFirstOuting).
RoomFigures brickRooms(const cli::Suite& suite, const std::string& noise, mapping::Strategy strategy,
                       bool afterFirstOuting = false) {
  cli::SuiteSettings s;
  s.afterFirstOuting = afterFirstOuting;
  s.strategy = strategy;
  s.noise = noise;
  s.seeds = roomSeeds();
  s.robot = *sim::robotByName("brick");
  s.startJitterDeg = kJitterDeg;
  s.squareAtStart = true;
  cli::ProgressLine progress(
      std::cerr, cli::stderrIsTerminal(),
      progressLabel("acceptance", "brick rooms, " + noise + (afterFirstOuting ? " after a first outing" : "") + ", " +
                                      mapping::strategyName(strategy)),
      suite.scenarios.size() * static_cast<size_t>(roomSeeds()));
  const report::ExperimentTable t =
      cli::runSuite(suite, s, [&](size_t, size_t, const std::string&) { progress.tick(); });
  RoomFigures f;
  double room = 0, occupied = 0, wrong = 0, unsafe = 0;
  for (const report::ExperimentRow& row : t.rows) {
    for (const report::RunResult& r : row.perSeed) {
      ++f.runs;
      f.detected += r.detectedPct;
      f.worst = std::min(f.worst, r.detectedPct);
      f.lost += r.lost > 0.5 ? 1 : 0;
      room += r.actualFree + r.actualOccupied;
      occupied += r.actualOccupied;
      wrong += r.wrongCells;
      unsafe += r.unsafeFree;
      f.headingOffPct += r.headingOffPct;
      f.positionOffPct += r.positionOffPct;
    }
  }
  f.squaring = t.squaring();
  f.detected /= std::max(1, f.runs);
  f.headingOffPct /= std::max(1, f.runs);
  f.positionOffPct /= std::max(1, f.runs);
  f.wrongPct = room > 0 ? 100.0 * wrong / room : 0;
  f.unsafePct = occupied > 0 ? 100.0 * unsafe / occupied : 0;
  return f;
}

// "mean / rms" of the squared heading over the runs whose sweep found the walls.
std::string squaredText(const report::ExperimentTable::Squaring& s) {
  return s.squared == 0 ? "-" : formatNumber(s.meanDeg, 2) + " / " + formatNumber(s.rmsDeg, 2);
}

// Houses: the brick under `nxt`, jitter 10, one strategy; mean and worst agreement, and at the rooms' best frames.
struct HouseFigures {
  double agreement = 0, worst = 100, bestFrames = 0;
  int runs = 0;
  int everyRoom = 0;  // runs that mapped every reachable plan room to >= 90 % (planCoverageOnGrid)
};

HouseFigures houses(const std::vector<fs::path>& plans, mapping::Strategy strategy) {
  HouseFigures f;
  cli::ProgressLine progress(std::cerr, cli::stderrIsTerminal(),
                             progressLabel("acceptance", "houses, nxt, " + mapping::strategyName(strategy)),
                             plans.size() * kHouseSeeds);
  for (const fs::path& p : plans) {
    worlds::SiteLoad l = worlds::loadSite(p.string(), sim::robotByName("brick")->cellCm);
    if (!l.site || !l.site->start) throw cli::CliError(l.error.empty() ? p.string() + ": no start" : l.error);
    const house::HousePlanLoad plan = house::loadHouseExpo(p.string());
    if (!plan.plan) throw cli::CliError(plan.error);
    for (int seed = 1; seed <= kHouseSeeds; ++seed) {
      house::HouseConfig c;
      c.robot = *sim::robotByName("brick");
      c.startPose = *l.site->start;
      c.startJitterDeg = kJitterDeg;
      c.squareAtStart = true;
      c.noise = *sim::noiseProfileByName("nxt");
      c.seed = static_cast<uint64_t>(seed);
      c.strategy = strategy;
      house::HouseMapper m(*l.site, c);
      m.run();
      const double a = house::scoreHouse(m).agreementPct();
      f.agreement += a;
      f.worst = std::min(f.worst, a);
      f.bestFrames += house::scoreWithBestFrames(house::houseInWorld(m)).score.agreementPct();
      const house::PlanCoverage cover = house::planCoverageOnGrid(m, *plan.plan);
      f.everyRoom += cover.covered == cover.reachable ? 1 : 0;
      ++f.runs;
      progress.tick();
    }
  }
  f.agreement /= std::max(1, f.runs);
  f.bestFrames /= std::max(1, f.runs);
  return f;
}

// One row: what, propagation, frontier, target, and whether the better of the two meets it.
std::vector<std::string> row(const std::string& what, double prop, double front, const std::string& target,
                             bool higherIsBetter, double goal, int decimals = 1) {
  const double better = higherIsBetter ? std::max(prop, front) : std::min(prop, front);
  const bool met = higherIsBetter ? better >= goal : better <= goal;
  return {what, formatNumber(prop, decimals), formatNumber(front, decimals), target, met ? "met" : "MISS"};
}

}  // namespace

int runAcceptanceBench() {
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path root = worldsRoot();
  const cli::Suite suite = cli::loadSuite((root / "seed-appendix-a").string(), 20);
  std::vector<fs::path> plans;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(root / "houseexpo", ec))
    if (e.path().extension() == ".json") plans.push_back(e.path());
  std::sort(plans.begin(), plans.end());

  const RoomFigures p = brickRooms(suite, "nxt", mapping::Strategy::Propagation);
  const RoomFigures fr = brickRooms(suite, "nxt", mapping::Strategy::Frontier);
  const RoomFigures up = brickRooms(suite, "nxt-uncalibrated", mapping::Strategy::Propagation);
  const RoomFigures uf = brickRooms(suite, "nxt-uncalibrated", mapping::Strategy::Frontier);
  const RoomFigures lp = brickRooms(suite, "nxt-uncalibrated", mapping::Strategy::Propagation, true);
  const RoomFigures lf = brickRooms(suite, "nxt-uncalibrated", mapping::Strategy::Frontier, true);
  const HouseFigures hp = houses(plans, mapping::Strategy::Propagation);
  const HouseFigures hf = houses(plans, mapping::Strategy::Frontier);

  std::cout << "\nreal-room acceptance (issue 18; the brick robot, 20 cm cells, set down up to " << kJitterDeg
            << " degrees off square; brick rooms: the " << suite.scenarios.size() << " published layouts, seeds 1-"
            << roomSeeds() << "; houses: " << plans.size() << " HouseExpo plans, seeds 1-" << kHouseSeeds << ")\n";
  const double nxtBest = std::max(p.detected, fr.detected);
  const double gap = nxtBest - std::max(up.detected, uf.detected);
  const double learntGap = nxtBest - std::max(lp.detected, lf.detected);
  const std::vector<std::vector<std::string>> rows = {
      row("brick rooms, nxt: mean detected %", p.detected, fr.detected, ">= 97", true, 97),
      row("brick rooms, nxt: worst run detected %", p.worst, fr.worst, ">= 90", true, 90),
      row("brick rooms, nxt: lost runs", p.lost, fr.lost, "0", false, 0, 0),
      row("brick rooms, nxt: wrong cells % of the room", p.wrongPct, fr.wrongPct, "<= 2", false, 2, 2),
      row("brick rooms, nxt: unsafe free % of occupied", p.unsafePct, fr.unsafePct, "<= 1", false, 1, 2),
      {"brick rooms, nxt: % of actions with the heading > 40 mrad off", formatNumber(p.headingOffPct, 1),
       formatNumber(fr.headingOffPct, 1), "(info)", "measured"},
      {"brick rooms, nxt: % of actions with the centre > 1/4 cell off", formatNumber(p.positionOffPct, 1),
       formatNumber(fr.positionOffPct, 1), "(info)", "measured"},
      {"brick rooms, nxt: squared heading, deg clockwise (mean / rms)", squaredText(p.squaring),
       squaredText(fr.squaring), "(info)", "measured"},
      {"brick rooms, nxt-uncalibrated: mean detected %", formatNumber(up.detected, 1), formatNumber(uf.detected, 1),
       "(info)", "measured"},
      {"uncalibrated: points under nxt (the better of each)", "", formatNumber(gap, 1), "<= 2",
       gap <= 2 ? "met" : "MISS"},
      {"nxt-uncalibrated after a first outing: mean detected %", formatNumber(lp.detected, 1),
       formatNumber(lf.detected, 1), "(info)", "measured"},
      {"... with its learnt wheels: points under nxt", "", formatNumber(learntGap, 1), "<= 2",
       learntGap <= 2 ? "met" : "MISS"},
      row("houses, nxt: mean agreement %", hp.agreement, hf.agreement, ">= 95", true, 95),
      row("houses, nxt: worst run agreement %", hp.worst, hf.worst, ">= 85", true, 85),
      {"houses, nxt: mean at the rooms' best frames %", formatNumber(hp.bestFrames, 1), formatNumber(hf.bestFrames, 1),
       "(info)", "measured"},
      {"houses: runs mapping every reachable plan room (>= 90 %)",
       std::to_string(hp.everyRoom) + " of " + std::to_string(hp.runs),
       std::to_string(hf.everyRoom) + " of " + std::to_string(hf.runs), "every run",
       std::max(hp.everyRoom - hp.runs, hf.everyRoom - hf.runs) == 0 ? "met" : "MISS"},
  };
  printColumns({"figure", "propagation", "frontier", "target", "result"}, rows);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "(" << p.runs + fr.runs + up.runs + uf.runs + lp.runs + lf.runs << " room runs (and a first outing "
            << "before each of the last " << lp.runs + lf.runs << ") and " << hp.runs + hf.runs << " house runs in "
            << formatNumber(wall, 0) << " s wall)\n";
  return 0;
}

}  // namespace nxtmap::bench
