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
  double bytesPerChange = 0;       // every byte brick -> PC (status, pose, deltas...) per cell change
  double deltaBytesPerChange = 0;  // bytes of the map deltas that arrived, per cell change
  uint64_t changes = 0;
  double meanLagMs = 0, p95LagMs = 0, maxLagMs = 0;
  uint32_t runMs = 0;
  bool equal = false;
  // MapSync's scan work: per scan (one buildDelta or pending call) and per brick step of 1 ms
  // (every transmit call of the step).
  uint64_t scans = 0;
  double bytesPerScan = 0, cellsPerScan = 0;
  uint32_t maxStepBytes = 0, maxStepCells = 0, maxStepScans = 0;
  uint32_t capacityCells = 0;
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

  std::map<std::pair<int, int>, std::pair<CellState, uint32_t>>
      changedAt;  // brick state and since when, not yet on the PC
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
  LinkFigures f;
  uint64_t bytesSum = 0, cellsSum = 0;
  while (h.nowMs() < 3600000 && (brick.mode() != protocol::BrickMode::Done || !changedAt.empty())) {
    const protocol::MapSync::Work before = brick.link().mapSync().work();
    h.tick();
    const protocol::MapSync::Work after = brick.link().mapSync().work();
    const uint32_t bytes = after.bytesCompared - before.bytesCompared,
                   cells = after.cellsExamined - before.cellsExamined;
    const uint32_t scans = after.scans - before.scans;
    f.scans += scans;
    bytesSum += bytes;
    cellsSum += cells;
    f.maxStepBytes = std::max(f.maxStepBytes, bytes);
    f.maxStepCells = std::max(f.maxStepCells, cells);
    f.maxStepScans = std::max(f.maxStepScans, scans);
    sample();
  }
  f.bytesPerScan = f.scans ? static_cast<double>(bytesSum) / static_cast<double>(f.scans) : 0;
  f.cellsPerScan = f.scans ? static_cast<double>(cellsSum) / static_cast<double>(f.scans) : 0;
  f.capacityCells =
      static_cast<uint32_t>(brick.grid().capacityWidth()) * static_cast<uint32_t>(brick.grid().capacityHeight());
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
  LinkFigures figures[2];
  for (bool lossy : {false, true}) {
    const LinkFigures f = measure(*load.world, col, row, lossy);
    figures[lossy ? 1 : 0] = f;
    std::printf("%-22s %14.1f %14.1f %9llu %12.1f %11.0f %11.0f %10s\n", lossy ? "5 % bytes damaged" : "clean",
                f.bytesPerChange, f.deltaBytesPerChange, static_cast<unsigned long long>(f.changes), f.meanLagMs,
                f.p95LagMs, f.maxLagMs, f.equal ? "yes" : "NO");
  }
  std::printf(
      "(bytes/change counts every byte the brick sends - deltas, status, pose - per cell whose state changed;\n"
      " delta B/chg only the map-delta frames that arrived intact;\n"
      " lag: from a change of the brick's grid to the same state in the PC's copy, brick ticks of 1 ms)\n");
  // The brick's CPU cost of the link is MapSync's scan of the grid against the PC's shadow.
  const uint32_t cap = figures[0].capacityCells;
  std::printf("\nMapSync scan work (the brick's CPU cost of transmit), same runs; grid capacity %u cells = %u bytes:\n",
              cap, cap / 4);
  std::printf("%-22s %7s %15s %15s %15s %15s %15s\n", "link", "scans", "bytes cmp/scan", "cells dec/scan",
              "step max bytes", "step max cells", "before: cells");
  for (int k = 0; k < 2; ++k) {
    const LinkFigures& f = figures[k];
    std::printf("%-22s %7llu %15.1f %15.2f %15u %15u %15u\n", k ? "5 % bytes damaged" : "clean",
                static_cast<unsigned long long>(f.scans), f.bytesPerScan, f.cellsPerScan, f.maxStepBytes,
                f.maxStepCells, cap);
  }
  std::printf(
      "(bytes cmp: grid bytes compared with the shadow, a 32-bit word at a time; cells dec: cells decoded one by\n"
      " one (runs and their gaps, partial bytes); step max: all scans of the worst 1 ms brick step (at most %u "
      "scans).\n"
      " before: the cell-by-cell scan of 8aca170 decoded every cell of the capacity, grid and shadow, every scan.\n"
      " Brick target: a transmit <= 20,000 instructions with nothing to send, <= 48,000 with a full delta; the\n"
      " instruction counts (ARM7TDMI Thumb -Os under Unicorn) are in the link2 report, not measured here)\n",
      std::max(figures[0].maxStepScans, figures[1].maxStepScans));
}

}  // namespace nxtmap::bench
