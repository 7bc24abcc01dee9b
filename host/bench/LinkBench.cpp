#include "host/bench/LinkBench.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include "host/link/LinkHarness.hpp"
#include "host/sim/World.hpp"

namespace nxtmap::bench {
namespace {

struct LinkFigures {
  double bytesPerChange = 0;     // every byte brick -> PC (status, pose, deltas...) per cell change
  double deltaBytesPerChange = 0;  // bytes of the map deltas that arrived, per cell change
  uint64_t changes = 0;
  double meanLagMs = 0, p95LagMs = 0, maxLagMs = 0;
  uint32_t runMs = 0;
  bool equal = false;
};

LinkFigures measure(const sim::World& world, int col, int row, bool lossy) {
  link::SimBrickConfig bc;
  bc.run.startCol = col;
  bc.run.startRow = row;
  bc.actionMs = 20;
  link::SimBrick brick(world, bc);
  link::Session pc(link::SessionConfig{0xBE7C4u, 250, 250});
  link::HarnessConfig hc;
  if (lossy) {
    hc.toPc = link::LossConfig::fivePercent(11);
    hc.toBrick = link::LossConfig::fivePercent(12);
  }
  link::LinkHarness h(brick, pc, hc);
  h.runUntil([&] { return pc.connected(); }, 60000);
  const uint64_t bytesAtStart = h.wireBytesToPc();
  pc.explore();

  std::map<std::pair<int, int>, std::pair<CellState, uint32_t>> changedAt;  // brick state and since when, not yet on the PC
  std::map<std::pair<int, int>, CellState> last;
  std::vector<double> lags;
  uint64_t changes = 0;
  auto sample = [&] {
    const Bounds w = brick.grid().window();
    for (int y = w.minY; y <= w.maxY; ++y) {
      for (int x = w.minX; x <= w.maxX; ++x) {
        const Cell c{static_cast<int16_t>(x), static_cast<int16_t>(y)};
        const CellState s = brick.grid().at(c);
        auto& prev = last[{x, y}];
        if (s != prev) {
          prev = s;
          ++changes;
          changedAt[{x, y}] = {s, h.nowMs()};
        }
        const auto it = changedAt.find({x, y});
        if (it != changedAt.end() && pc.map().at(c) == it->second.first) {
          lags.push_back(h.nowMs() - it->second.second);
          changedAt.erase(it);
        }
      }
    }
  };
  while (h.nowMs() < 3600000 && (brick.mode() != protocol::BrickMode::Done || !changedAt.empty())) {
    h.tick();
    sample();
  }
  LinkFigures f;
  f.runMs = h.nowMs();
  f.changes = changes;
  f.bytesPerChange = changes ? static_cast<double>(h.wireBytesToPc() - bytesAtStart) / static_cast<double>(changes) : 0;
  f.deltaBytesPerChange = changes ? static_cast<double>(pc.counters().deltaBytes) / static_cast<double>(changes) : 0;
  std::sort(lags.begin(), lags.end());
  if (!lags.empty()) {
    double sum = 0;
    for (double l : lags) sum += l;
    f.meanLagMs = sum / static_cast<double>(lags.size());
    f.p95LagMs = lags[lags.size() * 95 / 100];
    f.maxLagMs = lags.back();
  }
  f.equal = changedAt.empty();
  return f;
}

}  // namespace

void printLinkBench(const std::string& worldPath, int col, int row) {
  sim::WorldLoad load = sim::World::load(worldPath);
  if (!load.world) {
    std::printf("link: cannot load %s: %s\n", worldPath.c_str(), load.error.c_str());
    return;
  }
  std::printf("\nradio link at 460800 baud, %s from (%d,%d), stand-in brick (core explorer + BrickLink):\n",
              worldPath.c_str(), col, row);
  std::printf("%-22s %14s %14s %9s %12s %11s %11s %10s\n", "link", "bytes/change", "delta B/chg", "changes",
              "lag mean ms", "lag p95 ms", "lag max ms", "PC = brick");
  for (bool lossy : {false, true}) {
    const LinkFigures f = measure(*load.world, col, row, lossy);
    std::printf("%-22s %14.1f %14.1f %9llu %12.1f %11.0f %11.0f %10s\n", lossy ? "5 % bytes damaged" : "clean",
                f.bytesPerChange, f.deltaBytesPerChange, static_cast<unsigned long long>(f.changes), f.meanLagMs,
                f.p95LagMs, f.maxLagMs, f.equal ? "yes" : "NO");
  }
  std::printf("(bytes/change counts every byte the brick sends - deltas, status, pose - per cell whose state changed;\n"
              " delta B/chg only the map-delta frames that arrived intact;\n"
              " lag: from a change of the brick's grid to the same state in the PC's copy, brick ticks of 1 ms)\n");
}

}  // namespace nxtmap::bench
