// EmuBench: the emulated brick's budgets, measured on the real firmware image: RAM high-water (stack
// painting), the most instructions of one sensor update, and emulated robot time vs wall time.
#pragma once
#include <string>

namespace nxtmap::bench {

// Runs the firmware (build/firmware/nxtmap-sim.elf, or NXTMAP_FIRMWARE) on published rooms of scenarioDir; prints
// one line per run plus the verdicts. Returns the number of targets missed.
int runEmuBench(const std::string& scenarioDir);

}  // namespace nxtmap::bench
