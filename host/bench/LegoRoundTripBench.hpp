// LegoRoundTripBench: how long a PC tool waits for the brick's answer to one of LEGO's direct commands,
// measured through the emulated brick (real firmware, emulated Bluetooth link) on the emulated clock, at idle
// and while the robot explores. Targets (issue 20): <= 60 ms idle, <= 100 ms while driving.
#pragma once
#include <string>

namespace nxtmap::bench {

// Runs nxtmap-sim.elf (NXTMAP_FIRMWARE overrides) on scenarioDir's occupancy-120 room; prints the round trips
// against their targets. Returns the number of targets missed.
int runLegoRoundTripBench(const std::string& scenarioDir);

}  // namespace nxtmap::bench
