// EmulatedRun: one run of a firmware image in the emulated brick on a world: boots it, presses Enter to
// start the exploration, runs until the firmware reports the exploration done (symbol g_explorerDone != 0),
// a fault, or the time limit; then collects the measurements (RAM high-water, instructions per sensor
// update, emulated vs wall time). Shared by `nxtmap emulate`, the benchmark and the end-to-end tests.
#pragma once

#include "host/emu/Brick.hpp"
#include "host/emu/ElfImage.hpp"
#include "host/sim/Site.hpp"
#include "host/sim/World.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace nxtmap::emu {

// The firmware's map as it exports it when done (symbol g_mapExport, layout in /work notes and below):
// uint32 magic "MAP1", int16 minX, minY, width, height, then 2-bit CellState values, row-major.
struct ExportedMap {
  int minX = 0, minY = 0, width = 0, height = 0;
  std::vector<uint8_t> states;  // width * height CellState values
  // The state of explorer cell (x, y); Unknown (0) outside the exported window.
  uint8_t at(int x, int y) const;
};

struct EmulatedRunOptions {
  BrickConfig brick;              // start, heading, noise, seed, link, realtime (brick.machine.realtime)
  double maxSeconds = 3600.0;     // emulated time limit
  double pressEnterAtS = 1.0;     // when the "user" presses Enter (< 0: never)
  bool stopWhenExplored = true;   // end the run when the firmware reports the exploration done
  bool stopWhenPcLeaves = false;  // end the run when a PC that was connected disconnects
  // Called at every event boundary with the emulated cycle count (e.g. a test driving the PC side
  // of the link in step with the brick); returning true ends the run.
  std::function<bool(uint64_t cycles)> onEvent;
  std::string timedFunction = "nxtmapSensorUpdate";  // timed when the image has it
  bool profileWorstUpdate = false;  // keep where the costliest sensor update's instructions went (slower)
};

struct EmulatedRunReport {
  bool finished = false;  // the firmware reported the exploration done
  bool pcLeft = false;    // the run ended because the PC disconnected (stopWhenPcLeaves)
  EmuFault fault;
  double emulatedSeconds = 0.0;
  double wallSeconds = 0.0;
  double cpuSeconds = 0.0;  // host CPU time (the wall time also counts other processes on a busy machine)
  double speedRatio() const { return wallSeconds > 0.0 ? emulatedSeconds / wallSeconds : 0.0; }
  double cpuSpeedRatio() const { return cpuSeconds > 0.0 ? emulatedSeconds / cpuSeconds : 0.0; }
  uint64_t executed = 0, irqs = 0, idles = 0, slices = 0;
  RamUse ram;
  std::optional<uint32_t> staticRamBudget;  // the firmware's own __static_ram figure, if it has one
  uint64_t sensorUpdates = 0;               // timed-function calls (or g_sensorUpdates)
  uint64_t maxPerUpdate = 0;                // most instructions in one sensor update
  std::vector<FunctionCost> worstUpdate;    // profileWorstUpdate: that update's instructions by function
  uint64_t maxBusy = 0;                     // longest stretch between two idles
  uint64_t avrGood = 0, avrBad = 0, pings = 0;
  double drivenCm = 0.0;
  bool btPortOpen = false, btConnected = false, btStreaming = false;
  uint64_t btToPc = 0, btFromPc = 0;
  double xCm = 0.0, yCm = 0.0, headingDeg = 0.0;
};

class EmulatedRun {
 public:
  // image must outlive the run; the site's scene is shared with it.
  EmulatedRun(const ElfImage& image, const sim::Site& site, const EmulatedRunOptions& options);
  EmulatedRun(const ElfImage& image, const sim::World& world, const EmulatedRunOptions& options);
  // Runs to the end (done / fault / limit). Returns the report.
  EmulatedRunReport run();
  Brick& brick() { return *brick_; }
  // Reads a little-endian word of guest memory by symbol; nullopt if the symbol is missing.
  std::optional<uint32_t> readSymbolWord(const std::string& name) const;
  std::optional<uint8_t> readSymbolByte(const std::string& name) const;
  // The exported map, if the image has g_mapExport and it carries the magic.
  std::optional<ExportedMap> exportedMap() const;

 private:
  const ElfImage& image_;
  EmulatedRunOptions options_;
  std::unique_ptr<Brick> brick_;
  bool timed_ = false;
};

}  // namespace nxtmap::emu
