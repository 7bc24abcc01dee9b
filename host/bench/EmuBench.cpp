#include "host/bench/EmuBench.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

#include "host/cli/ExperimentRunner.hpp"
#include "host/emu/EmulatedRun.hpp"

namespace nxtmap::bench {
namespace {
constexpr uint32_t kRamTarget = 24 * 1024;
constexpr uint64_t kUpdateTarget = 48000;
constexpr double kSpeedTarget = 20.0;
constexpr double kLimitS = 1800.0;  // emulated seconds per room at most
}  // namespace

int runEmuBench(const std::string& scenarioDir) {
  const char* env = std::getenv("NXTMAP_FIRMWARE");
  const std::string fw = env ? env : "build/firmware/nxtmap-sim.elf";
  std::cout << "\nemulated brick: " << fw << " (real firmware, instruction by instruction; published geometry)\n";
  emu::ElfLoad load = emu::ElfImage::load(fw);
  if (!load.image) {
    std::cout << "  SKIPPED: " << load.error << " (make firmware)\n";
    return 1;
  }
  const emu::ElfImage& image = *load.image;
  const cli::Suite suite = cli::loadSuite(scenarioDir);
  // Three rooms by default (fewest, middle, most obstacles); NXTMAP_EMU_BENCH_ROOMS=all for all 18.
  std::vector<size_t> picks;
  const char* rooms = std::getenv("NXTMAP_EMU_BENCH_ROOMS");
  if (rooms && std::string(rooms) == "all") {
    for (size_t i = 0; i < suite.scenarios.size(); ++i) picks.push_back(i);
  } else {
    for (const char* id : {"occ089", "occ120", "occ139"})
      for (size_t i = 0; i < suite.scenarios.size(); ++i)
        if (suite.scenarios[i].id == id) picks.push_back(i);
  }
  uint32_t worstRam = 0;
  uint64_t worstUpdate = 0;
  double worstSpeed = 1e9, worstCpuSpeed = 1e9;
  bool allDone = true;
  std::printf("  %-8s %-6s %8s %8s %8s %8s %8s %7s %7s %10s %8s\n", "run", "end", "robot s", "wall s", "speed", "cpu s",
              "cpu spd", "RAM B", "stack B", "max/update", "updates");
  for (size_t i : picks) {
    const report::Scenario& sc = suite.scenarios[i];
    emu::EmulatedRunOptions o;
    o.brick.startCol = sc.startCol;
    o.brick.startRow = sc.startRow;
    o.maxSeconds = kLimitS;
    emu::EmulatedRun run(image, suite.world(sc), o);
    const emu::EmulatedRunReport r = run.run();
    const char* end = r.fault ? "FAULT" : r.finished ? "done" : "limit";
    std::printf("  %-8s %-6s %8.1f %8.2f %7.1fx %8.2f %7.1fx %7u %7u %10llu %8llu\n", sc.id.c_str(), end,
                r.emulatedSeconds, r.wallSeconds, r.speedRatio(), r.cpuSeconds, r.cpuSpeedRatio(), r.ram.total(),
                r.ram.stackBytes, static_cast<unsigned long long>(r.maxPerUpdate),
                static_cast<unsigned long long>(r.sensorUpdates));
    std::fflush(stdout);
    if (r.fault) std::printf("    fault: %s\n", r.fault.describe().c_str());
    worstRam = std::max(worstRam, r.ram.total());
    worstUpdate = std::max(worstUpdate, r.maxPerUpdate);
    worstSpeed = std::min(worstSpeed, r.speedRatio());
    worstCpuSpeed = std::min(worstCpuSpeed, r.cpuSpeedRatio());
    allDone = allDone && r.finished;
  }
  int missed = 0;
  auto verdict = [&](bool ok) {
    if (!ok) ++missed;
    return ok ? "PASS" : "MISS";
  };
  std::printf("  RAM high-water (static + painted stack)  %7u B   target <= %u B   %s\n", worstRam, kRamTarget,
              verdict(worstRam <= kRamTarget));
  std::printf("  instructions in one sensor update        %7llu     target <= %llu    %s\n",
              static_cast<unsigned long long>(worstUpdate), static_cast<unsigned long long>(kUpdateTarget),
              verdict(worstUpdate > 0 && worstUpdate <= kUpdateTarget));
  std::printf("  robot time vs wall time, whole room      %7.1fx    target >= %.0fx       %s\n", worstSpeed,
              kSpeedTarget, verdict(worstSpeed >= kSpeedTarget));
  std::printf("  robot time vs host CPU time (info)       %7.1fx\n", worstCpuSpeed);
  std::printf("  every room explored to the end            %s\n", verdict(allDone));
  return missed;
}

}  // namespace nxtmap::bench
