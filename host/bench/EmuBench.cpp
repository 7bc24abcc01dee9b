#include "host/bench/EmuBench.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <vector>

#include "host/cli/Args.hpp"
#include "host/emu/EmulatedRun.hpp"
#include "host/report/ExperimentTable.hpp"

namespace nxtmap::bench {
namespace {
constexpr uint32_t kRamTarget = 24 * 1024;
constexpr uint64_t kUpdateTarget = 48000;
constexpr double kSpeedTarget = 20.0;
constexpr double kDefaultLimitS = 120.0;  // emulated seconds per room at most (NXTMAP_EMU_BENCH_SECONDS)

struct Room {
  std::string map;
  int col, row;
};
}  // namespace

int runEmuBench(const std::string& scenarioDir) {
  namespace fs = std::filesystem;
  const char* env = std::getenv("NXTMAP_FIRMWARE");
  const std::string fw = env ? env : "build/firmware/nxtmap.elf";
  std::cout << "\nemulated brick: " << fw << " (real firmware, instruction by instruction)\n";
  emu::ElfLoad load = emu::ElfImage::load(fw);
  if (!load.image) {
    std::cout << "  SKIPPED: " << load.error << " (make firmware)\n";
    return 1;
  }
  const emu::ElfImage& image = *load.image;
  const char* limitEnv = std::getenv("NXTMAP_EMU_BENCH_SECONDS");
  const double kLimitS = limitEnv && std::atof(limitEnv) > 0 ? std::atof(limitEnv) : kDefaultLimitS;
  // The firmware explores in 0.20 m cells: the published rooms' layouts at that cell size.
  const double cellM = 0.20;
  const std::vector<Room> rooms = {{"occupancy-089.map", 1, 20}, {"occupancy-139.map", 1, 20}};
  uint32_t worstRam = 0;
  uint64_t worstUpdate = 0;
  double worstSpeed = 1e9;
  bool allDone = true;
  std::printf("  %-18s %-10s %9s %9s %9s %10s %11s %8s\n", "room", "end", "emu s", "wall s", "speed", "RAM B",
              "max/update", "updates");
  for (const Room& room : rooms) {
    const fs::path path = fs::path(scenarioDir) / room.map;
    sim::WorldLoad w = sim::World::loadMovingAi(path.string(), cellM);
    if (!w.world) {
      std::cout << "  " << room.map << ": " << w.error << "\n";
      allDone = false;
      continue;
    }
    emu::EmulatedRunOptions o;
    o.brick.startCol = room.col;
    o.brick.startRow = room.row;
    o.maxSeconds = kLimitS;
    emu::EmulatedRun run(image, *w.world, o);
    const emu::EmulatedRunReport r = run.run();
    const char* end = r.fault ? "FAULT" : r.finished ? "done" : "limit";
    std::printf("  %-18s %-10s %9.1f %9.2f %8.1fx %10u %11llu %8llu\n", room.map.c_str(), end, r.emulatedSeconds,
                r.wallSeconds, r.speedRatio(), r.ram.total(), static_cast<unsigned long long>(r.maxPerUpdate),
                static_cast<unsigned long long>(r.sensorUpdates));
    if (r.fault) std::printf("    fault: %s\n", r.fault.describe().c_str());
    worstRam = std::max(worstRam, r.ram.total());
    worstUpdate = std::max(worstUpdate, r.maxPerUpdate);
    worstSpeed = std::min(worstSpeed, r.speedRatio());
    allDone = allDone && r.finished;
  }
  int missed = 0;
  auto verdict = [&](bool ok) {
    if (!ok) ++missed;
    return ok ? "PASS" : "MISS";
  };
  std::printf("  RAM high-water (static + painted stack)  %6u B   target <= %u B   %s\n", worstRam, kRamTarget,
              verdict(worstRam <= kRamTarget));
  std::printf("  instructions in one sensor update        %6llu     target <= %llu    %s\n",
              static_cast<unsigned long long>(worstUpdate), static_cast<unsigned long long>(kUpdateTarget),
              verdict(worstUpdate > 0 && worstUpdate <= kUpdateTarget));
  std::printf("  emulated vs wall time                    %6.1fx    target >= %.0fx       %s\n", worstSpeed,
              kSpeedTarget, verdict(worstSpeed >= kSpeedTarget));
  std::printf("  whole room explored within %.0f s          %s\n", kLimitS, verdict(allDone));
  return missed;
}

}  // namespace nxtmap::bench
